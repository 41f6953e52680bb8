"""The README's *Teaching with yaseer*: three commands, then the notebook open in a browser.

The first two commands (a virtual environment, ``pip install -e '.[jupyter]'``) are what
this test environment was made with (``.ci/run`` runs all three in its clean clone); here
the third runs as the README gives it, with the environment activated as the first command
activates it, a port of its own, and a stand-in browser that notes the address Jupyter
opens.  That address is then opened in headless chromium, which must show the notebook's
cells.  The commands the section names afterwards must be found on PATH.
"""

from __future__ import annotations

import os
import re
import shlex
import shutil
import signal
import socket
import subprocess
import sys
import time
import tomllib
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent  # the environment's bin directory (what activating it puts first on PATH)
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def teaching_commands(page: Path, heading: str) -> list[str]:
    """The shell commands of the first ``sh`` block after ``heading`` on ``page``, comments dropped."""
    text = page.read_text()
    section = text[text.index(heading):]
    block = re.search(r"```sh\n(.*?)```", section, re.S)[1]
    return [line.split("  #")[0].strip() for line in block.splitlines() if line.strip()]


README_COMMANDS = teaching_commands(ROOT / "README.md", "## Teaching with yaseer")


def test_the_readme_opens_with_its_two_commands_then_teaches_in_three():
    text = (ROOT / "README.md").read_text()
    assert text.index("```sh\npython3 -m venv .venv && .venv/bin/pip") < text.index("## Teaching with yaseer")
    assert text.index("## Teaching with yaseer") == text.index("\n## ") + 1  # the first section
    assert README_COMMANDS == [
        "python3 -m venv .venv && . .venv/bin/activate",
        "pip install -q -e '.[jupyter]'",
        "jupyter notebook notebooks/classroom.ipynb",
    ]
    assert teaching_commands(ROOT / "docs" / "classroom.md", "## The first ten minutes") == README_COMMANDS


def test_the_jupyter_extra_installs_a_front_end_and_it_is_here():
    from importlib import metadata

    extra = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]["jupyter"]
    fronts = [r for r in extra if re.match(r"(notebook|jupyterlab)\b", r)]
    assert fronts, extra
    assert metadata.version(re.match(r"[\w-]+", fronts[0])[0])  # installed in this (test) environment too
    assert (BIN / "jupyter").exists() and (BIN / "jupyter-notebook").exists()


def activated_environment(tmp_path: Path) -> dict:
    """The environment of a shell after ``. .venv/bin/activate``, Jupyter's own files kept in ``tmp_path``."""
    env = dict(os.environ, VIRTUAL_ENV=str(BIN.parent), PATH=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}")
    for name in ("RUNTIME", "CONFIG", "DATA"):
        env[f"JUPYTER_{name}_DIR"] = str(tmp_path / name.lower())
    return env


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def test_the_third_command_opens_the_notebook_in_the_browser(tmp_path):
    browser = tmp_path / "browser.sh"
    opened = tmp_path / "opened.txt"
    browser.write_text(f"#!/bin/sh\necho \"$1\" >> {shlex.quote(str(opened))}\n")
    browser.chmod(0o755)
    env = activated_environment(tmp_path)
    env["BROWSER"] = str(browser)
    port = _free_port()
    command = shlex.split(README_COMMANDS[2]) + [f"--port={port}", "--ServerApp.port_retries=0"]
    if os.geteuid() == 0:  # Jupyter refuses root unless told; a teacher's account is not root
        command.append("--allow-root")
    # The class's copy of the notebook: Jupyter keeps checkpoints beside the notebook it opens.
    (tmp_path / "clone" / "notebooks").mkdir(parents=True)
    shutil.copyfile(ROOT / "notebooks" / "classroom.ipynb", tmp_path / "clone" / "notebooks" / "classroom.ipynb")
    server = subprocess.Popen(command, cwd=tmp_path / "clone", env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, start_new_session=True)
    try:
        deadline = time.monotonic() + 240
        while not (opened.exists() and opened.read_text().strip()):
            assert server.poll() is None, server.stdout.read()
            assert time.monotonic() < deadline, "Jupyter opened no browser in 240 s"
            time.sleep(0.5)
        page = Path(opened.read_text().split()[0].removeprefix("file://"))
        address = re.search(r'url=(http[^"]+)"', page.read_text())[1]
        assert re.fullmatch(rf"http://(localhost|127\.0\.0\.1):{port}/(tree|notebooks)/classroom\.ipynb\?token=\w+",
                            address), address
        with urllib.request.urlopen(address, timeout=60) as answer:
            assert answer.status == 200 and "Jupyter" in answer.read().decode()
        if CHROMIUM is None:
            pytest.skip("chromium is not installed (Debian: apt-get install chromium): the server answered, "
                        "but the page was not opened in a browser")
        shown = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                                f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=60000",
                                "--window-size=1280,2000", "--dump-dom", address],
                               capture_output=True, text=True, timeout=240)
        assert "The Al-Yaseer examples in class" in shown.stdout  # the first cell, rendered
        assert "../listings/example1.bas" in shown.stdout  # a code cell's text in the editor
    finally:
        os.killpg(server.pid, signal.SIGTERM)
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(server.pid, signal.SIGKILL)
            server.wait()


def test_after_activation_the_readmes_commands_are_on_path(tmp_path):
    script = (f". {shlex.quote(str(BIN / 'activate'))} && cd {shlex.quote(str(tmp_path))} && command -v yaseer && "
              f"yaseer run {ROOT / 'listings' / 'example5.bas'} | head -n 1 && "
              f"yaseer plot {ROOT / 'listings' / 'example5.bas'} --out figures")
    if not (BIN / "activate").exists():  # a Python not in a virtual environment: PATH as activation sets it
        script = script.split(" && ", 1)[1]
    done = subprocess.run(["bash", "-c", script], env=activated_environment(tmp_path), capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    found, first_row, *written = done.stdout.splitlines()
    assert Path(found) == BIN / "yaseer"
    assert first_row.split() == ["360.10", "-8.80", "857.64", "809.98"]  # the README's sample, first row
    assert written == ["figures/example5.png", "figures/example5.svg"]
