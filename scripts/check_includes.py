#!/usr/bin/env python3
"""Checks the include direction of the project's layers and of core/'s folders.

    python3 scripts/check_includes.py [ROOT]     # exit 1 and one line per broken rule
    python3 scripts/check_includes.py --self-test  # exit 0 if the checker catches a planted violation

The rule (docs/ARCHITECTURE.md): a folder of core/ may include only the folders listed for it
below (and itself); nothing includes another folder's detail/; core/ includes neither
vcg_adapters/ nor filter_geodesic_remesh/ nor Qt or MeshLab; vcg_adapters/ does not include
filter_geodesic_remesh/. Only quoted project includes ("core/...") and the MeshLab/Qt headers
are looked at; system headers are free.
"""
import pathlib
import re
import sys
import tempfile

# Which core folders each core folder may include (besides itself).
ALLOWED = {
    "base": set(),
    "mesh": {"base"},
    "geodesic": {"base", "mesh"},
    "measure": {"base", "mesh"},
    "field": {"base", "mesh", "geodesic"},
    "remesh": {"base", "mesh", "geodesic", "field", "measure"},
    "segment": {"base", "mesh", "geodesic", "field", "measure"},
    "flatten": {"base", "mesh", "geodesic", "measure"},
    "atlas": {"base", "mesh", "geodesic", "field", "measure", "segment", "flatten"},
    "param": {"base", "mesh", "geodesic", "field", "measure", "remesh"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
MESHLAB_OR_QT = re.compile(r"^(common/|Q[A-Za-z]+$|Qt[A-Za-z]*/|GL/)")


def folder_of(path):
    """('core', 'geodesic') for core/geodesic/x.h, ('vcg_adapters', None) for vcg_adapters/x.h."""
    parts = pathlib.PurePosixPath(path).parts
    if parts and parts[0] == "core":
        return "core", parts[1] if len(parts) > 2 else None
    return (parts[0] if parts else None), None


def violations(root):
    root = pathlib.Path(root)
    found = []
    for layer in ("core", "vcg_adapters", "filter_geodesic_remesh"):
        for src in sorted((root / layer).rglob("*")):
            if src.suffix not in (".h", ".cpp", ".hpp", ".inl"):
                continue
            rel = src.relative_to(root).as_posix()
            _, folder = folder_of(rel)
            text = src.read_text(errors="replace")
            for m in INCLUDE.finditer(text):
                kind, target = m.group(1), m.group(2)
                line = text.count("\n", 0, m.start()) + 1
                where = f"{rel}:{line}: includes {target}"
                if layer == "core" and MESHLAB_OR_QT.match(target):
                    found.append(f"{where}: core/ must not use MeshLab or Qt")
                if kind != '"':
                    continue
                t_layer, t_folder = folder_of(target)
                if layer == "core" and t_layer in ("vcg_adapters", "filter_geodesic_remesh"):
                    found.append(f"{where}: core/ must not include {t_layer}/")
                if layer == "vcg_adapters" and t_layer == "filter_geodesic_remesh":
                    found.append(f"{where}: vcg_adapters/ must not include filter_geodesic_remesh/")
                if t_layer != "core" or t_folder is None:
                    continue
                if "/detail/" in target and t_folder != folder:
                    found.append(f"{where}: detail/ of core/{t_folder} is private to that folder")
                if layer == "core":
                    if folder not in ALLOWED:
                        found.append(f"{where}: core/{folder} is not a known folder (add it to ALLOWED)")
                    elif t_folder != folder and t_folder not in ALLOWED[folder]:
                        found.append(f"{where}: core/{folder} may not include core/{t_folder}")
    return found


def self_test():
    """A tree with one legal include and three broken rules: all three must be reported."""
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        files = {
            "core/mesh/a.h": '#include "core/base/status.h"\n',
            "core/mesh/b.h": '#include "core/geodesic/fast_marching.h"\n',           # upward
            "core/remesh/c.h": '#include "core/geodesic/detail/unfold.h"\n',         # detail
            "core/base/d.h": '#include <QString>\n',                                  # Qt in core
            "vcg_adapters/e.h": '#include "core/geodesic/fast_marching.h"\n',
        }
        for name, text in files.items():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text)
        (root / "filter_geodesic_remesh").mkdir()
        found = violations(root)
        expected = ["core/base/d.h", "core/mesh/b.h", "core/remesh/c.h"]
        got = sorted(v.split(":")[0] for v in found)
        if got != expected:
            print(f"self-test failed: expected violations in {expected}, got {found}")
            return 1
        print("self-test: the checker reports all three planted violations and nothing else")
        return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    root = argv[1] if len(argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    found = violations(root)
    for v in found:
        print(v)
    print(f"include direction: {len(found)} violation(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
