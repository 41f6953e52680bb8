"""The README's promises about the listings: its two commands, its sample output, its links."""

from __future__ import annotations

import re

from listing_runs import GOLDEN, ROOT

README = (ROOT / "README.md").read_text()


def test_readme_gives_exactly_the_two_commands_first():
    blocks = re.findall(r"```sh\n(.*?)```", README, flags=re.S)
    assert blocks[0].splitlines() == [
        "python3 -m venv .venv && .venv/bin/pip install -q -e '.[test]' && .venv/bin/yaseer run listings/example1.bas",
        ".venv/bin/python -m pytest -q",
    ]


def test_readme_sample_is_example5s_golden_output():
    sample = re.search(r"\$ yaseer run listings/example5.bas\n(.*?)```", README, flags=re.S).group(1)
    golden = (GOLDEN / "example5.txt").read_text().splitlines()
    shown = [line for line in sample.splitlines() if line.strip() != "…"]
    assert len(shown) >= 5
    for line in shown:
        assert line in golden, line
    assert [golden.index(line) for line in shown] == sorted(golden.index(line) for line in shown)



def test_readme_links_and_named_files_exist():
    targets = re.findall(r"\]\(([^)#]+)\)", README)
    targets += re.findall(r"`((?:docs|listings|programs|tests/benchmarks)/[^`*\s]+\.(?:md|bas|py|png))`", README)
    assert "listings/ERRATA.md" in targets and "docs/example5.png" in targets
    missing = [target for target in targets if not (ROOT / target).exists()]
    assert missing == []
