"""Every code block of docs/python.md and docs/scale.md runs as a user would paste it.

A ```python block is saved as a script and run by this interpreter (the one CMake chose) in
a folder of its own, with the build's PYTHONPATH; a block of `>>>` lines is typed into the
interactive interpreter and each line it shows is checked against what the interpreter
printed; a ```sh block runs in bash from a folder where `build` is this build. A line of a
script that is an expression followed by a comment holding a Python literal
(`round(alpha.min(), 4)   # -0.9211`) quotes a value: it is run as an assertion that the
expression equals it. A block that cannot run here (a signature list, a cluster's address) is
marked `<!-- not run: why -->` on the line above its fence, and each page's count of them is
fixed below, so a block left out by mistake fails as surely as one that breaks.

The Dask snippet of scale.md is the case that made this file (issue 57): pasted at a script's
top level it made every worker process start a cluster of its own and hung, which a
subprocess with a time limit turns into a failure."""

import ast
import importlib.util
import io
import os
import pathlib
import re
import subprocess
import sys
import tokenize

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
PAGES = ("python.md", "scale.md")
# The blocks each page keeps unrun on purpose, and the values its scripts quote.
NOT_RUN = {"python.md": 1, "scale.md": 2}
QUOTED = {"python.md": 6, "scale.md": 0}
# A guard, not a timing assertion: a block that hangs (the unguarded Dask snippet) fails.
LIMIT_S = 300

FENCE = re.compile(r"^```(\S*)\s*$")
MARK = re.compile(r"^<!-- not run: (.+) -->$")


def blocks(page):
    """The fenced blocks of docs/`page`: (line of the fence, language, text, why not run)."""
    found, lines = [], (REPOSITORY / "docs" / page).read_text(encoding="utf-8").splitlines()
    i = 0
    while i < len(lines):
        opening = FENCE.match(lines[i])
        if not opening:
            i += 1
            continue
        end = next(j for j in range(i + 1, len(lines)) if lines[j].strip() == "```")
        before = next((lines[j].strip() for j in range(i - 1, -1, -1) if lines[j].strip()), "")
        mark = MARK.match(before)
        found.append((i + 1, opening.group(1), "\n".join(lines[i + 1:end]) + "\n", mark.group(1) if mark else None))
        i = end + 1
    return found


def with_quoted_values_checked(script):
    """`script` with each line `EXPRESSION  # LITERAL` made an assertion; and their count."""
    comments = {}
    for token in tokenize.generate_tokens(io.StringIO(script).readline):
        if token.type == tokenize.COMMENT:
            comments[token.start[0]] = token.start[1]
    lines, checks = script.splitlines(), 0
    for number, column in comments.items():
        line = lines[number - 1]
        code, comment = line[:column].rstrip(), line[column + 1:].strip()
        try:
            statement = ast.parse(code.strip())
            ast.literal_eval(comment)
        except (SyntaxError, ValueError):
            continue
        if len(statement.body) != 1 or not isinstance(statement.body[0], ast.Expr):
            continue
        indent = code[:len(code) - len(code.lstrip())]
        lines[number - 1] = (f"{indent}_quoted = ({code.strip()}); "
                             f"assert _quoted == ({comment}), {line.strip()!r} + ' is ' + repr(_quoted)")
        checks += 1
    return "\n".join(lines) + "\n", checks


def matplotlib_stub(folder):
    """A stand-in for matplotlib, which the module does not need, when it is not installed:
    every name a call that takes anything and unpacks into as many of itself as asked."""
    package = folder / "matplotlib"
    package.mkdir()
    stub = ("class _Anything:\n"
            "    def __call__(self, *args, **kwargs): return self\n"
            "    def __getattr__(self, name): return self\n"
            "    def __iter__(self): return iter((self, self))\n"
            "def __getattr__(name): return _Anything()\n")
    (package / "__init__.py").write_text(stub)
    (package / "pyplot.py").write_text(stub)


def environment(folder):
    env = dict(os.environ, MPLBACKEND="Agg")
    if importlib.util.find_spec("matplotlib") is None:
        matplotlib_stub(folder)
        env["PYTHONPATH"] = os.pathsep.join([str(folder), env.get("PYTHONPATH", "")])
    return env


def build_folder():
    """This build: CTest's PYTHONPATH is <build>/python."""
    python = os.environ.get("PYTHONPATH", "").split(os.pathsep)[0]
    if not python:
        pytest.fail("PYTHONPATH is not set: run these tests through CTest (ctest -R python)")
    return pathlib.Path(python).resolve().parent


def failure(what, run):
    return f"{what} failed (exit {run.returncode}):\n--- stdout\n{run.stdout}\n--- stderr\n{run.stderr}"


def run_script(text, folder):
    script, _ = with_quoted_values_checked(text)
    (folder / "block.py").write_text(script, encoding="utf-8")
    run = subprocess.run([sys.executable, "block.py"], cwd=folder, env=environment(folder), capture_output=True,
                         text=True, timeout=LIMIT_S)
    assert run.returncode == 0, failure("the script", run)


def run_transcript(text, folder):
    """`>>>` lines typed into `python -i`; every other line is what the interpreter shows."""
    typed = [line[4:] for line in text.splitlines() if line.startswith((">>> ", "... "))]
    shown = [line for line in text.splitlines() if line.strip() and not line.startswith((">>> ", "... "))]
    # The document the transcript loads: the v1 four-bar of the fuzz corpus, its coupler -70.
    good = (REPOSITORY / "tests" / "fuzz" / "corpus" / "documents" / "fourbar_v1.linkwright").read_text()
    assert '"coupler": 70' in good
    (folder / "bad.linkwright").write_text(good.replace('"coupler": 70', '"coupler": -70'))
    run = subprocess.run([sys.executable, "-q", "-i"], cwd=folder, env=environment(folder), input="\n".join(typed) + "\n",
                         capture_output=True, text=True, timeout=LIMIT_S)
    assert run.returncode == 0, failure("the session", run)
    printed = (run.stdout + run.stderr).replace(">>> ", "").splitlines()
    at = 0
    for line in shown:
        assert line in printed[at:], f"{line!r} not shown, in order; the session showed:\n{run.stdout}{run.stderr}"
        at = printed.index(line, at) + 1


def run_shell(text, folder):
    if "/usr/bin/python3" in text and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        pytest.skip(f"the block runs Debian's /usr/bin/python3; this build is for {sys.executable}")
    (folder / "build").symlink_to(build_folder(), target_is_directory=True)
    run = subprocess.run(["bash", "-euo", "pipefail", "-c", text], cwd=folder, env=environment(folder),
                         capture_output=True, text=True, timeout=LIMIT_S)
    assert run.returncode == 0, failure("the commands", run)


RUNNABLE = [pytest.param(page, line, language, text, id=f"{page}:{line}")
            for page in PAGES for line, language, text, why in blocks(page) if why is None]


def test_each_page_marks_the_blocks_it_does_not_run():
    for page in PAGES:
        found = blocks(page)
        assert len(found) > NOT_RUN[page], page
        assert sum(why is not None for *_, why in found) == NOT_RUN[page], page
        for line, language, text, why in found:
            if why is None:
                assert language in ("python", "sh"), f"{page}:{line}: a ```{language} block this test cannot run"
        quoted = sum(with_quoted_values_checked(text)[1] for _, language, text, why in found
                     if why is None and language == "python" and not text.startswith(">>> "))
        assert quoted == QUOTED[page], page


@pytest.mark.parametrize("page, line, language, text", RUNNABLE)
def test_the_block_runs_as_pasted(page, line, language, text, tmp_path):
    if language == "sh":
        run_shell(text, tmp_path)
    elif text.startswith(">>> "):
        run_transcript(text, tmp_path)
    else:
        run_script(text, tmp_path)
