#!/usr/bin/env python3
"""Every repository path docs/design.md names exists (docs.design_names in CTest).

A path is a backticked token that starts with a top-level folder of the repository. It
names a file or folder when one of these exists:
  - the path itself, or the path with .hpp, .cpp, .h, .sh or .py appended (a stem such as
    `certify/riccati_filter` names its header and source);
  - for a layer's public header written short, `LAYER/REST` = `LAYER/include/hinf/LAYER/REST`
    (`sdp/dual_bound.hpp`, `runtime/lti_controller.hpp`), and `runtime_yaml/REST` =
    `runtime/yaml/include/hinf/runtime_yaml/REST`.
Braces list alternatives (`sim/{include/hinf/sim,src}/gyroless_{run,report}`): each name in
the last brace group must exist under at least one of the others.
Prints each name that does not exist; exit 1 if any, 0 otherwise.
  design_names.py REPOSITORY_ROOT
"""
import itertools
import os
import re
import sys

ROOTS = ("apps", "bench", "certify", "cmake", "codegen", "common", "configs", "docs", "fuzz", "lmi",
         "models", "python", "runtime", "runtime_yaml", "scripts", "sdp", "sim", "synth", "tests", ".ci")
SUFFIXES = ("", ".hpp", ".cpp", ".h", ".sh", ".py")


def exists(root, path):
    path = path.rstrip("/")
    candidates = [path]
    layer, _, rest = path.partition("/")
    if rest:
        candidates.append(f"{layer}/include/hinf/{layer}/{rest}")
        if layer == "runtime_yaml":  # the runtime's file readers live in runtime/yaml/
            candidates.append(f"runtime/yaml/include/hinf/runtime_yaml/{rest}")
    return any(os.path.exists(os.path.join(root, c + s)) for c in candidates for s in SUFFIXES)


def groups(token):
    """The token split into literal text and brace groups: ["a/", ["x", "y"], "/b"]."""
    parts, pos = [], 0
    for m in re.finditer(r"\{([^{}]*)\}", token):
        parts.append(token[pos:m.start()])
        parts.append(m.group(1).split(","))
        pos = m.end()
    parts.append(token[pos:])
    return parts


def missing(root, token):
    parts = groups(token)
    brace_at = [i for i, p in enumerate(parts) if isinstance(p, list)]
    if not brace_at:
        return [] if exists(root, token) else [token]
    last = brace_at[-1]
    others = [parts[i] if isinstance(parts[i], list) else [parts[i]] for i in range(last)]
    out = []
    for name in parts[last]:
        tail = name + "".join(p for p in parts[last + 1:] if isinstance(p, str))
        if not any(exists(root, "".join(prefix) + tail) for prefix in itertools.product(*others)):
            out.append(token + " (" + name + ")")
    return out


def main():
    root = sys.argv[1]
    text = open(os.path.join(root, "docs", "design.md"), encoding="utf-8").read()
    bad = []
    for token in sorted(set(re.findall(r"`([^`\s]+)`", text))):
        token = token.rstrip(".,:;")
        if token.split("/")[0] not in ROOTS or "/" not in token or "*" in token or "<" in token:
            continue
        bad += missing(root, token)
    for b in bad:
        print("docs/design.md names a path that does not exist: " + b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
