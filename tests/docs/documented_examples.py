"""Every documented example runs as written (issue "A tool people enjoy", item 7).

The examples: each shell line of a fenced code block in README.md and docs/*.md that calls
`build/bin/hinf-synth`, `build/bin/hinf-sim` or the bare names (a line ending in `|` or `\\`
continues on the next), and the worked example at the end of every `--help` (hinf-synth's
subcommands through `hinf-synth help SUBCOMMAND`, and hinf-sim's). A synopsis (a line with
`[` or an upper-case placeholder such as SCENARIO.yaml or DIR) is not an example and is left
out. Each example runs with bash, in the order of the files (README.md first, then docs/ by
name, then the --help examples), in one scratch directory that links configs/, tests/ and
scripts/ of the source tree and build/bin/ of the build under test — so a later example may
read what an earlier one wrote (gains.yaml) — and must exit 0.

Usage: documented_examples.py SOURCE_DIR BIN_DIR [--list]
"""
import os
import re
import subprocess
import sys
import tempfile
import time

EXECUTABLE = re.compile(r"^(build/bin/)?hinf-(synth|sim)\b")
PLACEHOLDER = re.compile(r"^[A-Z][A-Z0-9_]*(\.[a-z]+)?$")  # SCENARIO.yaml, DIR, N
FENCE = re.compile(r"^\s*```")
SCRIPT = re.compile(r"^\s*(for|while|if)\b")
SETUP = re.compile(r"^\s*(\./scripts/install-deps|cmake )")


def command_part(line):
    """The line without its trailing comment (a '#' after a space, outside quotes)."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip()
    return line.rstrip()


def is_synopsis(command):
    first = command.split("|")[0]
    return "[" in first or any(PLACEHOLDER.match(t) for t in first.split())


def examples_in(path):
    """(line number, command) of each example in a Markdown file's fenced code blocks; a block
    with a shell loop is one example, a script, without its set-up lines (install, cmake: the
    build under test is the one the test runs against)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    out, i = [], 0
    while i < len(lines):
        if not FENCE.match(lines[i]):
            i += 1
            continue
        end = i + 1
        while end < len(lines) and not FENCE.match(lines[end]):
            end += 1
        block = lines[i + 1:end]
        if any(SCRIPT.match(l) for l in block) and any(EXECUTABLE.match(l.strip()) for l in block):
            script = [l for l in block if not SETUP.match(l)]
            out.append((i + 2, "\n".join(script)))
        else:
            out += commands_in(block, i + 2)
        i = end + 1
    return out


def commands_in(block, first_line):
    out, j = [], 0
    while j < len(block):
        line = block[j].strip()
        if EXECUTABLE.match(line):
            start, command = first_line + j, command_part(line)
            while command.endswith("|") or command.endswith("\\"):
                j += 1
                command = (command[:-1] if command.endswith("\\") else command) + " " + command_part(block[j].strip())
            if not is_synopsis(command):
                out.append((start, command))
        j += 1
    return out


def help_examples(bin_dir):
    """('--help of X', command) for every subcommand of hinf-synth and for hinf-sim."""
    synth = os.path.join(bin_dir, "hinf-synth")
    top = subprocess.run([synth, "--help"], capture_output=True, text=True, check=True).stdout
    section = top.split("Subcommands:", 1)[1].split("\n\n", 1)[0]
    subcommands = [l.split()[0] for l in section.splitlines() if l.startswith("  ") and l.split()[0] != "help"]
    out = []
    for sub in subcommands:
        text = subprocess.run([synth, "help", sub], capture_output=True, text=True, check=True).stdout
        out += [("hinf-synth help " + sub, command_part(l.split("Example:", 1)[1].strip()))
                for l in text.splitlines() if "Example:" in l]
    text = subprocess.run([os.path.join(bin_dir, "hinf-sim"), "--help"], capture_output=True, text=True).stdout
    out += [("hinf-sim --help", command_part(l.split("Example:", 1)[1].strip()))
            for l in text.splitlines() if "Example:" in l]
    if len(out) < len(subcommands) + 1:
        raise SystemExit("a --help has no 'Example:' line: %d examples for %d subcommands and hinf-sim"
                         % (len(out), len(subcommands)))
    return out


def main():
    source, bin_dir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    docs = os.path.join(source, "docs")
    files = [os.path.join(source, "README.md")] + sorted(
        os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    examples = [("%s:%d" % (os.path.relpath(p, source), n), c) for p in files for n, c in examples_in(p)]
    examples += help_examples(bin_dir)
    if "--list" in sys.argv:
        for where, command in examples:
            print("%-40s %s" % (where, command))
        return 0
    failed = []
    with tempfile.TemporaryDirectory(prefix="hinf-doc-examples-") as scratch:
        for name in ("configs", "tests", "scripts"):
            os.symlink(os.path.join(source, name), os.path.join(scratch, name))
        os.makedirs(os.path.join(scratch, "build"))
        os.symlink(bin_dir, os.path.join(scratch, "build", "bin"))
        for where, command in examples:
            runnable = re.sub(r"(^|(?<=[\s;|&(]))hinf-(synth|sim)\b", r"\1build/bin/hinf-\2", command,
                              flags=re.M)
            start = time.time()
            r = subprocess.run(["bash", "-o", "pipefail", "-c", runnable], cwd=scratch, capture_output=True,
                               text=True, timeout=900)
            print("%-40s exit %d  %6.1f s  %s" % (where, r.returncode, time.time() - start, command), flush=True)
            if r.returncode != 0:
                failed.append(where)
                print(r.stdout[-2000:] + r.stderr[-2000:], flush=True)
    print("%d examples, %d failed%s" % (len(examples), len(failed), (": " + ", ".join(failed)) if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
