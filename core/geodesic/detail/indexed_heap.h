// IndexedHeap: a binary min-heap of vertices keyed by distance, with decrease-key.
//
// Each vertex is in the heap at most once (its position is tracked), so fast marching pops no
// stale entries. Memory: one int per vertex plus the entries in the heap.
#pragma once

#include <vector>

namespace gr {

class IndexedHeap {
 public:
  struct Entry {
    double key;
    int v;
  };

  /// Makes room for vertices 0..n-1; the heap must be empty.
  void resize(int n) { pos_.assign(n, -1); }
  bool empty() const { return heap_.empty(); }
  const Entry& top() const { return heap_.front(); }
  const std::vector<Entry>& entries() const { return heap_; }

  /// Inserts v with `key`, or lowers its key if it is in the heap (a higher key is ignored).
  void pushOrDecrease(int v, double key) {
    int i = pos_[v];
    if (i < 0) {
      i = static_cast<int>(heap_.size());
      heap_.push_back({key, v});
    } else if (key < heap_[i].key) {
      heap_[i].key = key;
    } else {
      return;
    }
    siftUp(i);
  }

  /// Removes and returns the vertex with the smallest key.
  int pop() {
    const int v = heap_.front().v;
    pos_[v] = -1;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      heap_[0] = last;
      pos_[last.v] = 0;
      siftDown(0);
    }
    return v;
  }

  void clear() {
    for (const Entry& e : heap_) pos_[e.v] = -1;
    heap_.clear();
  }

 private:
  void siftUp(int i) {
    const Entry e = heap_[i];
    while (i > 0) {
      const int parent = (i - 1) / 2;
      if (heap_[parent].key <= e.key) break;
      heap_[i] = heap_[parent];
      pos_[heap_[i].v] = i;
      i = parent;
    }
    heap_[i] = e;
    pos_[e.v] = i;
  }
  void siftDown(int i) {
    const int n = static_cast<int>(heap_.size());
    const Entry e = heap_[i];
    for (;;) {
      int child = 2 * i + 1;
      if (child >= n) break;
      if (child + 1 < n && heap_[child + 1].key < heap_[child].key) ++child;
      if (e.key <= heap_[child].key) break;
      heap_[i] = heap_[child];
      pos_[heap_[i].v] = i;
      i = child;
    }
    heap_[i] = e;
    pos_[e.v] = i;
  }

  std::vector<Entry> heap_;
  std::vector<int> pos_;
};

}  // namespace gr
