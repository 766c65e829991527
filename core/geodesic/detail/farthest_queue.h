// FarthestQueue: the vertex of largest U, for values that only decrease (farthest-point sampling).
//
// A bucket queue keyed by the leading bits of U's IEEE-754 representation (for doubles >= 0 the
// bit pattern is ordered like the value): 2^kSubBits buckets per octave, each a plain list of
// vertex numbers. update(v) appends v to the bucket of its current U, and leaves the entry of its
// old value behind; an entry is current while U[v] still falls in its bucket. top() scans the
// highest bucket with entries, drops the stale ones and returns its largest current value.
//
// Why not a binary heap with decrease-key: in sampling every vertex a new front improves moves
// from near the top of a max-heap to near its bottom, ~log V levels of cache misses; here it is
// one append. Because U only decreases, the
// highest non-empty bucket only moves down, so the empty buckets above it are never revisited.
// Cost: O(1) per update; top() is linear in the top bucket (a few vertices: those within 2^-kSubBits
// of the largest U). Memory: one int per update, compacted when stale entries dominate.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace gr {

class FarthestQueue {
 public:
  /// `U` is read at each call (it must outlive the queue). Values at or below `floor` (> 0) share
  /// the lowest bucket, which is still exact, only slower to scan; choose it well below the
  /// smallest spacing of interest.
  FarthestQueue(const std::vector<double>& U, double floor) : U_(U), baseKey_(key(floor)) {}

  /// Files v under its current U (>= 0, finite), after a decrease or for the first time.
  void update(int v) {
    const size_t b = bucket(U_[v]);
    if (b >= buckets_.size()) buckets_.resize(b + 1);
    buckets_[b].push_back(v);
    if (static_cast<long>(b) > highest_) highest_ = static_cast<long>(b);
    if (++entries_ > 4 * U_.size() + 1024) compact();
  }

  /// The filed vertex with the largest current U, the lowest number among equals; -1 if none.
  int top() {
    for (; highest_ >= 0; --highest_) {
      std::vector<int>& list = buckets_[highest_];
      int best = -1;
      size_t kept = 0;
      for (int v : list) {
        if (bucket(U_[v]) != static_cast<size_t>(highest_)) continue;  // stale: U fell since
        list[kept++] = v;
        if (best < 0 || U_[v] > U_[best] || (U_[v] == U_[best] && v < best)) best = v;
      }
      entries_ -= list.size() - kept;
      list.resize(kept);
      if (best >= 0) return best;
    }
    return -1;
  }

 private:
  static constexpr int kSubBits = 9;  ///< 512 buckets per octave: a bucket spans ~0.14% of U
  static uint64_t key(double u) {
    uint64_t bits;
    std::memcpy(&bits, &u, sizeof bits);
    return bits >> (52 - kSubBits);
  }
  size_t bucket(double u) const {
    const uint64_t k = key(u);
    return k > baseKey_ ? static_cast<size_t>(k - baseKey_) : 0;
  }
  /// Drops every stale entry (and duplicates of a vertex in the same bucket).
  void compact() {
    entries_ = 0;
    std::vector<char> seen(U_.size(), 0);
    for (size_t b = 0; b < buckets_.size(); ++b) {
      size_t kept = 0;
      for (int v : buckets_[b])
        if (!seen[v] && bucket(U_[v]) == b) {
          seen[v] = 1;
          buckets_[b][kept++] = v;
        }
      buckets_[b].resize(kept);
      entries_ += kept;
    }
  }

  const std::vector<double>& U_;
  uint64_t baseKey_;
  std::vector<std::vector<int>> buckets_;
  long highest_ = -1;  ///< no bucket above this one has entries
  size_t entries_ = 0;
};

}  // namespace gr
