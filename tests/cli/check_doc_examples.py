#!/usr/bin/env python3
"""Runs every command example of the manual with the built executable and compares its output
with the one documented, so that the manual cannot drift from what twinraster prints.

An example is a fenced block whose first line is a "$ " command and one of whose commands is
"$ twinraster ..." (variables, or a pipe, may come first); each "$ " line is a command (run by sh, with
`twinraster` the built executable, the block's commands in order in one scratch folder, so that
one may prepare a file for the next) and the lines up to the next one are its output, standard
output and standard error as a terminal shows them. The fence closing an example must be
backticks alone: a Markdown reader would keep the block open past one with text after it.

What the documented output may leave out (docs/testing.md, "The manual's examples run"):
  - a line that is exactly "..." stands for any number of lines, none included;
  - a line ending in " ..." stands for one line that starts with the text before it;
  - "<!-- example: not run: REASON -->" on the line before the block skips it, saying why.
What is compared after a narrow normalisation, the same on both sides:
  - a number followed by " ms" (a timing) and the CPU twin's thread count;
  - the first line of --version ("twinraster 0.1.0 (bbfb2c9-dirty)": the version and git describe);
  - this machine's lavapipe device name, release, LLVM version and CPU path, replaced by the
    reference machine's the manual was written on (REFERENCE below), when they differ.

Without files it also checks the counts of shipped scenes the manual states (STATED_COUNTS), and
that docs/json-output.md says what changed in every version of each --json output.

Run as: check_doc_examples.py --exe build/bin/twinraster --source <repository> [--update] [FILE.md...]
Without files, README.md and every docs/*.md. Exits 1 naming each drifted example (file and
line, the documented and the actual output). --update rewrites each drifted example's output
with this run's instead, keeping a "..." line and a "prefix ..." line where they still fit:
read the diff before committing it. --self-test proves the checker fails on a drifted example.
CTest runs both (tests/cli/CMakeLists.txt)."""

import argparse
import difflib
import os
import re
import shutil
import subprocess
import sys
import tempfile

# The machine the documented outputs come from: Debian 12's lavapipe on an AVX2 CPU.
REFERENCE = {"mesa": "22.3.6", "llvm": "15.0.6", "cpu_path": "x86-64 AVX2+FMA, 256-bit",
             "device": "llvmpipe (LLVM 15.0.6, 256 bits)"}

SKIP = re.compile(r"<!--\s*example:\s*not run:\s*(.+?)\s*-->")
TIMING = re.compile(r"\b\d+(\.\d+)? ms\b")
THREADS = re.compile(r"\(CPU twin, \d+ threads?\)")
VERSION_LINE = re.compile(r"^twinraster \d+\.\d+\.\d+( \([0-9a-zA-Z.-]+\))?$")
# Variables may come first, or a pipe into it.
RUNS_TWINRASTER = re.compile(r"^\$ (.*[|;&] *)?(\w+=\S* )*twinraster\b")
ELIDED = "..."
# A command and its output for the self-test, run after a command that makes "notes" a file.
JUNIT_IN_A_FILE = ("$ twinraster render scenes/cgfs-transforms.json --backend cpu --junit notes/j.xml\n"
                   "twinraster: --junit notes/j.xml: notes is a file, not a directory\n")
TIMEOUT_SECONDS = 120


def scene_files(source, folder, recursive=False):
    """The scene files (JSON) under scenes/FOLDER, but the million cubes, which no loop takes."""
    top = os.path.join(source, "scenes", folder)
    found = []
    for at, _, names in os.walk(top):
        found += [os.path.join(at, n) for n in names if n.endswith(".json") and n != "one-million-cubes.json"]
        if not recursive:
            break
    return found


# The counts of shipped scenes the manual states, each counted here: (file, the sentence with the
# number as its group, the count). A scene added or removed makes the sentence fail until it is
# corrected (or --update corrects it).
STATED_COUNTS = [
    ("docs/commands.md", r"Rendering the (\d+)\s+small scenes of `scenes/\*\.json` and `scenes/hard/`",
     lambda source: len(scene_files(source, "") + scene_files(source, "hard"))),
    ("docs/testing.md", r"`ShippedScenes\(\)` throws unless it finds the (\d+) scenes",
     lambda source: len(scene_files(source, "", recursive=True))),
    ("docs/testing.md", r"(\d+) hard scenes", lambda source: len(scene_files(source, "hard"))),
]


def check_stated_counts(source, update, report):
    """How many stated counts are wrong; with update, corrects them in place."""
    wrong = 0
    for name, sentence, count in STATED_COUNTS:
        path = os.path.join(source, name)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        found = re.search(sentence, text)
        if not found:
            report("%s: the sentence stating a count is gone: %s (tests/cli/check_doc_examples.py)" % (name, sentence))
            wrong += 1
            continue
        actual = count(source)
        if int(found.group(1)) == actual:
            continue
        wrong += 1
        line = text.count("\n", 0, found.start(1)) + 1
        report("%s:%d: says %s, but the repository has %d" % (name, line, found.group(1), actual))
        if update:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text[:found.start(1)] + str(actual) + text[found.end(1):])
    return wrong


def check_version_notes(source, report):
    """How many versions of a --json output lack their row in json-output.md's "What changed in each
    version": every version after the first, of each format the page's table of outputs names."""
    with open(os.path.join(source, "docs", "json-output.md"), encoding="utf-8") as f:
        text = f.read()
    changes = re.search(r"\n## What changed in each version\n(.*?)\n## ", text, re.S)
    if not changes:
        report("docs/json-output.md: no \"## What changed in each version\" section")
        return 1
    noted = set(re.findall(r"^\| `([a-z-]+/\d+)` \|", changes.group(1), re.M))
    current = dict(re.findall(r"^\| `twinraster [^|]*\| `twinraster\.([a-z-]+)/(\d+)` \|", text, re.M))
    missing = 0
    for name, version in sorted(current.items()):
        for v in range(2, int(version) + 1):
            if "%s/%d" % (name, v) not in noted:
                report("docs/json-output.md: %s/%d has no row in \"What changed in each version\"" % (name, v))
                missing += 1
    if len(current) < 8:
        report("docs/json-output.md: only %d outputs found in its table of outputs" % len(current))
        missing += 1
    return missing


class Example:
    """One fenced block of commands and outputs, with where it sits in its file."""

    def __init__(self, path, first_line, last_line, skip_reason):
        self.path = path
        self.first_line = first_line  # the opening fence's index in the file's lines
        self.last_line = last_line  # the closing fence's
        self.skip_reason = skip_reason
        self.commands = []  # (line index of "$ ", command, documented output lines)

    def fence_is_open(self, lines):
        """Whether the closing fence has text after its backticks, which Markdown does not close on."""
        return self.last_line < len(lines) and lines[self.last_line].strip("` ") != ""


def find_examples(path, lines):
    """Every example block of a file's lines."""
    examples = []
    i = 0
    while i < len(lines):
        if not lines[i].startswith("```"):
            i += 1
            continue
        end = next((k for k in range(i + 1, len(lines)) if lines[k].startswith("```")), len(lines))
        body = lines[i + 1:end]
        if body and body[0].startswith("$ ") and any(RUNS_TWINRASTER.match(line) for line in body):
            skip = SKIP.search(lines[i - 1]) if i > 0 else None
            example = Example(path, i, end, skip.group(1) if skip else None)
            for k, line in enumerate(body, start=i + 1):
                if line.startswith("$ "):
                    example.commands.append((k, line[2:], []))
                else:
                    example.commands[-1][2].append(line)
            examples.append(example)
        i = end + 1
    return examples


class Machine:
    """What of this machine shows in outputs, against the reference machine's."""

    def __init__(self, exe):
        text = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=TIMEOUT_SECONDS).stdout
        path = re.search(r"^lavapipe's CPU path on this machine: (.+)$", text, re.M)
        # A distribution may append its package revision ("Mesa 25.0.7-2"); the twin names the release alone.
        release = re.search(r"llvmpipe, Mesa (\d+(?:\.\d+)+)\S* \(LLVM (\S+)\)", text)
        self.swaps = []  # (this machine's text as a pattern, the reference's)
        device = re.search(r"^  (?:lavapipe \()?(llvmpipe \([^)]*\))\)?: ", text, re.M)
        if device and device.group(1) != REFERENCE["device"]:
            self.swaps.append((re.escape(device.group(1)), REFERENCE["device"]))
        if path and path.group(1) != REFERENCE["cpu_path"]:
            self.swaps.append((re.escape(path.group(1)), REFERENCE["cpu_path"]))
        if release:
            mesa, llvm = release.groups()
            # Not in --version's table of known releases, which names LLVM by its major alone:
            # "Mesa 25.0.7 (LLVM 19), ..." is the same text on every machine.
            if mesa != REFERENCE["mesa"]:
                self.swaps.append((re.escape("Mesa " + mesa) + r"(?! \(LLVM \d+\))", "Mesa " + REFERENCE["mesa"]))
            if llvm != REFERENCE["llvm"]:
                self.swaps.append((re.escape("LLVM " + llvm) + r"\b", "LLVM " + REFERENCE["llvm"]))

    def as_reference(self, line):
        for here, there in self.swaps:
            line = re.sub(here, there, line)
        return line


def counted(n, noun):
    return "%d %s" % (n, noun if n == 1 else noun + "s")


def normalise(line):
    line = TIMING.sub("N ms", line)
    line = THREADS.sub("(CPU twin, N threads)", line)
    return VERSION_LINE.sub("twinraster VERSION", line)


def line_matches(documented, actual):
    if documented.endswith(" " + ELIDED):
        return normalise(actual).startswith(normalise(documented[:-len(ELIDED)]))
    return normalise(documented) == normalise(actual)


def output_matches(documented, actual):
    """Whether the actual lines are the documented ones, "..." standing for any run of lines."""
    if not documented:
        return not actual
    if documented[0] == ELIDED:
        return any(output_matches(documented[1:], actual[k:]) for k in range(len(actual) + 1))
    return bool(actual) and line_matches(documented[0], actual[0]) and output_matches(documented[1:], actual[1:])


def updated_output(documented, actual):
    """The actual lines, with the documented elisions kept where they still fit."""
    result, j = [], 0
    for i, line in enumerate(documented):
        if line == ELIDED:
            following = documented[i + 1] if i + 1 < len(documented) else None
            if following is None:
                j = len(actual)
            else:
                j = next((k for k in range(j, len(actual)) if line_matches(following, actual[k])), j)
            result.append(ELIDED)
        elif j < len(actual):
            result.append(line if line.endswith(" " + ELIDED) and line_matches(line, actual[j]) else actual[j])
            j += 1
    return result + actual[j:]


def scratch_folder(source, commands):
    """A folder for one example's commands: scenes/ linked and each repository file they name
    copied (its folder made for it), so that outputs land here and never in the repository. Other
    folders are left for the commands to make or refuse, as a user's would be."""
    folder = tempfile.mkdtemp(prefix="twinraster-doc-example-")
    os.symlink(os.path.abspath(os.path.join(source, "scenes")), os.path.join(folder, "scenes"))
    for word in re.split(r"[\s<>=]+", " ".join(commands)):
        if not word or word.startswith(("-", "/", "scenes/")) or "/" not in word:
            continue
        if os.path.isfile(os.path.join(source, word)):
            os.makedirs(os.path.join(folder, os.path.dirname(word)), exist_ok=True)
            shutil.copyfile(os.path.join(source, word), os.path.join(folder, word))
    return folder


def run_command(exe, folder, machine, command):
    """The command's output lines in folder, standard output and error interleaved, as the
    reference machine's."""
    bin_dir = tempfile.mkdtemp(prefix="twinraster-doc-bin-")
    os.symlink(os.path.abspath(exe), os.path.join(bin_dir, "twinraster"))
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))
    try:
        done = subprocess.run(["sh", "-c", command], cwd=folder, env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT_SECONDS)
        lines = done.stdout.splitlines()
    except subprocess.TimeoutExpired:
        lines = ["(no output: the command ran for over %d s)" % TIMEOUT_SECONDS]
    finally:
        shutil.rmtree(bin_dir)
    return [machine.as_reference(line) for line in lines]


def remove_folder(folder):
    """Removes a scratch folder, even where an example took write permission away (chmod 444)."""
    for at, dirs, files in os.walk(folder):
        for name in dirs + files:
            if not os.path.islink(os.path.join(at, name)):
                os.chmod(os.path.join(at, name), 0o755)
    shutil.rmtree(folder)


def check_file(exe, source, machine, path, update, report):
    """Runs each example of one file; returns (run, skipped, drifted) and with update rewrites it."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    run = skipped = drifted = 0
    replacements = []  # (first, last, new lines) of each drifted command's output
    shown = os.path.relpath(path, source)
    for example in find_examples(path, lines):
        if example.skip_reason:
            skipped += 1
            report("%s:%d: not run: %s" % (shown, example.first_line + 1, example.skip_reason))
            continue
        if example.fence_is_open(lines):
            drifted += 1
            report("%s:%d: the fence closing the example has text after it, so Markdown keeps the block open: "
                   "put the text on a line of its own" % (shown, example.last_line + 1))
        folder = scratch_folder(source, [command for _, command, _ in example.commands])
        for at, command, documented in example.commands:
            run += 1
            actual = run_command(exe, folder, machine, command)
            if output_matches(documented, actual):
                continue
            drifted += 1
            report("%s:%d: the output of `%s` drifted from the manual:" % (shown, at + 1, command))
            report("\n".join(difflib.unified_diff(documented, actual, "documented", "actual", lineterm="")))
            replacements.append((at + 1, at + 1 + len(documented), updated_output(documented, actual)))
        remove_folder(folder)
    if update and replacements:
        for first, last, new in reversed(replacements):
            lines[first:last] = new
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
        report("%s: %s rewritten" % (shown, counted(len(replacements), "example output")))
    return run, skipped, drifted


def self_test(exe, source):
    """The checker on a made-up page: a true example passes (one that prepares a file for its
    twinraster command too), a drifted one and a wrong elision fail, and so does a closing fence
    with text after it."""
    folder = tempfile.mkdtemp(prefix="twinraster-doc-self-test-")
    true_page = os.path.join(folder, "true.md")
    with open(true_page, "w", encoding="utf-8") as f:
        f.write("```\n$ twinraster rendr scenes/cgfs-transforms.json\n"
                "twinraster: unknown command \"rendr\" (did you mean \"render\"?)\nsee 'twinraster --help'\n```\n\n"
                "```\n$ twinraster --version\ntwinraster 9.9.9 (0000000)\nlavapipe's CPU path on this machine: ...\n"
                "...\n```\n\n<!-- example: not run: made up for this test -->\n```\n$ twinraster nothing\nnever\n```\n\n"
                "```\n$ touch notes\n" + JUNIT_IN_A_FILE + "```\n")
    # Each wrong page, with the line its drift is reported at.
    wrong_pages = {
        "a drifted line": ("```\n$ twinraster rendr scenes/cgfs-transforms.json\n"
                           "twinraster: unknown command \"rendr\" (did you mean \"explain\"?)\nsee 'twinraster --help'\n```\n",
                           2),
        "a missing line": ("```\n$ twinraster rendr scenes/cgfs-transforms.json\n"
                           "twinraster: unknown command \"rendr\" (did you mean \"render\"?)\n```\n", 2),
        "a prefix that no longer fits": ("```\n$ twinraster --version\ntwinraster 9.9.9\nthe CPU path: ...\n...\n```\n", 2),
        # After a command that makes notes a folder, the same render writes j.xml there: its refusal drifts.
        "an output that needs the command before it": ("```\n$ mkdir notes\n" + JUNIT_IN_A_FILE + "```\n", 3),
    }
    machine = Machine(exe)
    failures = []
    quiet = []
    run, skipped, drifted = check_file(exe, source, machine, true_page, False, quiet.append)
    if (run, skipped, drifted) != (4, 1, 0):
        failures.append("a true page: %d run, %d skipped, %d drifted (expected 4, 1, 0): %s" %
                        (run, skipped, drifted, "\n".join(quiet)))
    for what, (text, line) in wrong_pages.items():
        page = os.path.join(folder, "wrong.md")
        with open(page, "w", encoding="utf-8") as f:
            f.write(text)
        said = []
        if check_file(exe, source, machine, page, False, said.append)[2] != 1 or ":%d: the output of" % line not in said[0]:
            failures.append("%s was not caught at line %d: %s" % (what, line, said))
        check_file(exe, source, machine, page, True, lambda _: None)
        if check_file(exe, source, machine, page, False, said.append)[2] != 0:
            failures.append("%s still drifts after --update: %s" % (what, said))
    failures += self_test_open_fence(exe, source, machine, folder)
    failures += self_test_stated_counts(source, folder)
    shutil.rmtree(folder)
    for failure in failures:
        print("check_doc_examples --self-test: " + failure, file=sys.stderr)
    cases = 1 + len(wrong_pages) * 2 + 1 + 3
    print("check_doc_examples --self-test: %d of %d cases as expected" % (cases - len(failures), cases))
    return 1 if failures else 0


def self_test_open_fence(exe, source, machine, folder):
    """An example whose closing fence has text after it fails, though its output is right."""
    page = os.path.join(folder, "fence.md")
    with open(page, "w", encoding="utf-8") as f:
        f.write("```\n$ twinraster rendr scenes/cgfs-transforms.json\n"
                "twinraster: unknown command \"rendr\" (did you mean \"render\"?)\nsee 'twinraster --help'\n"
                "``` and then prose\n")
    said = []
    if check_file(exe, source, machine, page, False, said.append)[2] != 1 or ":5: the fence closing" not in said[0]:
        return ["a closing fence with text after it was not caught at line 5: %s" % said]
    return []


def self_test_stated_counts(source, folder):
    """A copy of the manual's pages with one stated count off by one must fail, and pass once
    updated; a json-output.md with a version's note missing must fail."""
    copy = os.path.join(folder, "source")
    os.makedirs(os.path.join(copy, "docs"))
    os.symlink(os.path.abspath(os.path.join(source, "scenes")), os.path.join(copy, "scenes"))
    for name in sorted({name for name, _, _ in STATED_COUNTS}):
        shutil.copyfile(os.path.join(source, name), os.path.join(copy, name))
    name, sentence, count = STATED_COUNTS[0]
    with open(os.path.join(copy, name), encoding="utf-8") as f:
        text = f.read()
    found = re.search(sentence, text)
    with open(os.path.join(copy, name), "w", encoding="utf-8") as f:
        f.write(text[:found.start(1)] + str(count(source) + 1) + text[found.end(1):])
    failures = []
    said = []
    if check_stated_counts(copy, False, said.append) != 1:
        failures.append("a stated count off by one was not caught: %s" % said)
    check_stated_counts(copy, True, lambda _: None)
    if check_stated_counts(copy, False, said.append) != 0:
        failures.append("a stated count still wrong after --update: %s" % said)
    # json-output.md without its render/4 row.
    with open(os.path.join(source, "docs", "json-output.md"), encoding="utf-8") as f:
        page = f.read()
    with open(os.path.join(copy, "docs", "json-output.md"), "w", encoding="utf-8") as f:
        f.write(re.sub(r"^\| `render/4` \|.*\n", "", page, flags=re.M))
    if check_version_notes(source, said.append) != 0 or check_version_notes(copy, said.append) != 1:
        failures.append("a version of render --json with no note was not caught: %s" % said)
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--update", action="store_true")
    parser.add_argument("--self-test", action="store_true")
    parser.add_argument("files", nargs="*")
    args = parser.parse_args()
    if args.self_test:
        return self_test(args.exe, args.source)
    files = args.files or [os.path.join(args.source, "README.md")] + sorted(
        os.path.join(args.source, "docs", name) for name in os.listdir(os.path.join(args.source, "docs"))
        if name.endswith(".md"))
    machine = Machine(args.exe)
    totals = [0, 0, 0]
    for path in files:
        counts = check_file(args.exe, args.source, machine, path, args.update, print)
        totals = [a + b for a, b in zip(totals, counts)]
    run, skipped, drifted = totals
    if not args.files:
        drifted += check_stated_counts(args.source, args.update, print)
        drifted += check_version_notes(args.source, print)
    print("check_doc_examples: %s run, %s not run, %d drifted (outputs, stated counts, version notes)" %
          (counted(run, "command"), counted(skipped, "example"), drifted))
    if run == 0:
        print("check_doc_examples: no example found: the manual's examples have moved or lost their \"$ \"")
        return 1
    return 1 if drifted and not args.update else 0


if __name__ == "__main__":
    sys.exit(main())
