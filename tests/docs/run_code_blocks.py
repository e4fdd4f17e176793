#!/usr/bin/python3
"""Runs every fenced code block of one markdown file, so that what the documentation shows
cannot go stale: a command, an option, a dataset name or an error message that changes breaks
this test.

usage: run_code_blocks.py FILE.md --source REPO --build BUILD --work DIR

The blocks of a file run in order, in one scratch folder DIR (emptied first) laid out like the
repository after a build: build/, configs/, scripts/, tests/, docs/, benchmarks/, include/ and
src/ are links to the real ones (nothing is written into them), results/ is an empty folder.
What a block writes there, a later block of the same file may read.

By the block's language:
  sh, bash, shell  bash -e, a fresh shell per block (no pipefail: `ncdump -h F | head` is a
                   fair thing to show, and its SIGPIPE no failure);
  console          `$ COMMAND` lines (a trailing backslash continues one) each run by bash; the
                   lines up to the next `$ ` are its output, stdout and stderr together, and must
                   match exactly (trailing blanks aside); the exit status is not checked: such
                   blocks show errors;
  python           /usr/bin/python3 (the interpreter with h5py, numpy and matplotlib);
  toml             read by `build/rocksweep info --config`: every key must be an option, in the
                   table it belongs to;
  text             an illustration (a tree, a synopsis): shown, not run;
  matlab           run by GNU Octave (octave-cli), which stands in for MATLAB: the readers use
                   only ncinfo/ncread, which both have.
A block without a language, or in any other, fails: tag it `text` to show it without running it.

Two markers, written where a reader sees what is going on:
  `# not run by tests/docs: REASON` as a line of a block: reported as not run, with the reason
      (it installs packages, needs a cluster, or takes many minutes);
  `<!-- docs-test setup: COMMAND -->` on a line of its own: COMMAND runs (bash, in DIR) before
      the blocks that follow, to make a file that a block not run would have made.

Open MPI refuses to start as root unless told; as root every block runs with
OMPI_ALLOW_RUN_AS_ROOT=1 and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1, which is what the README tells a
root user to set, and with oversubscription allowed (the test shares its cores).

Prints one line per block; exit status 1 if any block failed.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

LINKED = ("build", "configs", "scripts", "tests", "docs", "benchmarks", "include", "src")
PYTHON = "/usr/bin/python3"
TIMEOUT_S = 600
NOT_RUN = re.compile(r"^\s*#\s*not run by tests/docs:\s*(.+?)\s*$")
SETUP = re.compile(r"^\s*<!--\s*docs-test setup:\s*(.+?)\s*-->\s*$")
FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})\s*([^\s`]*)")
NOT_RUN_LANGUAGES = {"text": "an illustration"}


class Block:
    def __init__(self, line, language, body, setups):
        self.line, self.language, self.body, self.setups = line, language, body, setups


def blocks(path):
    """The fenced blocks of a markdown file, with the setup commands met before each."""
    found, setups = [], []
    lines = open(path, encoding="utf-8").read().split("\n")
    i = 0
    while i < len(lines):
        setup = SETUP.match(lines[i])
        if setup:
            setups.append(setup.group(1))
        fence = FENCE.match(lines[i])
        if not fence:
            i += 1
            continue
        indent, mark, language = fence.groups()
        start, body = i + 1, []
        i += 1
        while i < len(lines) and not lines[i].strip().startswith(mark):
            body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i])
            i += 1
        if i == len(lines):
            raise SystemExit("{}:{}: a code block without its closing {}".format(path, start, mark))
        found.append(Block(start, language.lower(), "\n".join(body) + "\n", setups))
        setups = []
        i += 1
    return found


def scratch(source, build, work):
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(os.path.join(work, "results"))
    for name in LINKED:
        target = build if name == "build" else os.path.join(source, name)
        if os.path.exists(target):
            os.symlink(target, os.path.join(work, name))


def environment():
    env = dict(os.environ, MPLBACKEND="Agg", OMPI_MCA_rmaps_base_oversubscribe="1")
    if os.geteuid() == 0:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return env


def run(argv, work, env, stdin_text=None):
    """(exit status, stdout and stderr together) of `argv` run in `work`."""
    try:
        p = subprocess.run(argv, cwd=work, env=env, input=stdin_text if stdin_text is not None else "",
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return 124, "timed out after {} s".format(TIMEOUT_S)
    return p.returncode, p.stdout


def console_steps(body):
    """[(command, expected output lines)] of a console block."""
    steps = []
    lines = body.rstrip("\n").split("\n")
    i = 0
    while i < len(lines):
        if not lines[i].startswith("$ "):
            raise ValueError("line {} of the block is neither a `$ ` command nor the output of one".format(i + 1))
        command = lines[i][2:]
        while command.endswith("\\") and i + 1 < len(lines):
            i += 1
            command = command[:-1] + " " + lines[i].lstrip("> ").strip()
        i += 1
        expected = []
        while i < len(lines) and not lines[i].startswith("$ "):
            expected.append(lines[i].rstrip())
            i += 1
        while expected and not expected[-1]:
            expected.pop()
        steps.append((command, expected))
    return steps


def run_console(block, work, env):
    """'' if every command of the block printed what the block shows, else what differed."""
    try:
        steps = console_steps(block.body)
    except ValueError as e:
        return str(e)
    for command, expected in steps:
        _, out = run(["bash", "-c", command], work, env)
        got = [line.rstrip() for line in out.rstrip("\n").split("\n")] if out.strip() else []
        if got != expected:
            return "$ {}\nexpected:\n{}\ngot:\n{}".format(command, "\n".join(expected), "\n".join(got))
    return ""


def run_block(block, work, env):
    """('ok' | 'not run: why' | 'FAILED', detail)"""
    for command in block.setups:
        status, out = run(["bash", "-e", "-c", command], work, env)
        if status != 0:
            return "FAILED", "setup `{}` exited {}:\n{}".format(command, status, out)
    for line in block.body.split("\n"):
        reason = NOT_RUN.match(line)
        if reason:
            return "not run: " + reason.group(1), ""
    language = block.language
    if language in NOT_RUN_LANGUAGES:
        return "not run: " + NOT_RUN_LANGUAGES[language], ""
    if language in ("sh", "bash", "shell"):
        status, out = run(["bash", "-e"], work, env, block.body)
    elif language == "python":
        status, out = run([PYTHON, "-"], work, env, block.body)
    elif language == "toml":
        path = os.path.join(work, "block_line{}.toml".format(block.line))
        with open(path, "w") as f:
            f.write(block.body)
        status, out = run(["build/rocksweep", "info", "--config", path], work, env)
    elif language == "matlab":
        path = os.path.join(work, "block_line{}.m".format(block.line))
        with open(path, "w") as f:
            f.write(block.body)
        status, out = run(["octave-cli", "--no-gui", "--quiet", "--norc", path], work, env)
    elif language == "console":
        diff = run_console(block, work, env)
        return ("FAILED", diff) if diff else ("ok", "")
    elif not language:
        return "FAILED", "a block without a language: tag it (`text` to show it without running it)"
    else:
        return "FAILED", "no rule for ```{} blocks (see tests/docs/run_code_blocks.py)".format(language)
    if status != 0:
        return "FAILED", "exit status {}:\n{}".format(status, out)
    return "ok", ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("markdown")
    ap.add_argument("--source", required=True, help="the repository")
    ap.add_argument("--build", required=True, help="the build folder, holding rocksweep")
    ap.add_argument("--work", required=True, help="scratch folder (emptied)")
    args = ap.parse_args()
    source, build, work = (os.path.abspath(p) for p in (args.source, args.build, args.work))
    name = os.path.relpath(os.path.abspath(args.markdown), source)
    found = blocks(args.markdown)
    scratch(source, build, work)
    env = environment()
    failed = 0
    for block in found:
        t0 = time.monotonic()
        verdict, detail = run_block(block, work, env)
        print("{}:{} {}: {} ({:.1f} s)".format(name, block.line, block.language or "(no language)", verdict,
                                               time.monotonic() - t0), flush=True)
        if verdict == "FAILED":
            failed += 1
            print("  " + detail.rstrip().replace("\n", "\n  "), flush=True)
    print("{}: {} code blocks, {} failed".format(name, len(found), failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
