"""What a run writes, and where: standard output, the --printer file, the program's own files
inside --files DIR, and the compiled-program cache; nothing in the installed package, the
home directory elsewhere or the current directory.  The README and ``run --help`` say so."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import yaseer

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = Path(yaseer.__file__).resolve().parent


def every_file(directory: Path) -> dict[str, int]:
    """Each file under ``directory`` (its modification time), but Python's own bytecode."""
    return {str(p.relative_to(directory)): p.stat().st_mtime_ns for p in directory.rglob("*")
            if p.is_file() and p.suffix != ".pyc"}


def test_a_run_writes_only_its_output_and_the_documented_cache(tmp_path):
    home, work, files, temporary = tmp_path / "home", tmp_path / "work", tmp_path / "files", tmp_path / "tmp"
    for directory in (home, work, files, temporary):
        directory.mkdir()
    listing = work / "w.bas"
    listing.write_text('10 OPEN "O", #1, "OUT.TXT": PRINT #1, 5: CLOSE\n20 PRINT 6: LPRINT 7\n')
    env = {k: v for k, v in os.environ.items() if k not in ("YASEER_CACHE_DIR", "XDG_CACHE_HOME")}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env.update(HOME=str(home), TMPDIR=str(temporary))
    package_before = every_file(PACKAGE)
    for _ in range(2):  # cold, then warm
        done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing), "--printer", "paper.txt",
                               "--files", str(files)], capture_output=True, text=True, env=env, cwd=work)
        assert (done.returncode, done.stdout, done.stderr) == (0, " 6 \n", "")
    assert every_file(PACKAGE) == package_before
    assert sorted(every_file(work)) == ["paper.txt", "w.bas"]
    assert sorted(every_file(files)) == ["OUT.TXT"]
    assert list(temporary.iterdir()) == []  # no parser tables, no probe file
    cache = home / ".cache" / "yaseer" / "compiled"
    written = sorted(every_file(home))
    assert written and all(name.startswith(".cache/yaseer/compiled/") for name in written)
    assert all(name.endswith(".bin") or Path(name).name.startswith("toolchain-") for name in written)
    assert cache.stat().st_mode & 0o777 == 0o700


def test_the_readme_and_run_help_name_the_cache():
    readme = " ".join((ROOT / "README.md").read_text().split())
    assert "What a run writes, and where" in readme and "~/.cache/yaseer/compiled" in readme
    assert "nothing inside the installed package" in readme.lower()
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", "--help"], capture_output=True, text=True)
    shown = " ".join(done.stdout.split())
    assert "~/.cache/yaseer/compiled" in shown and "YASEER_CACHE_DIR" in shown
    assert "nothing is written anywhere else" not in shown
