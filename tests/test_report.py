"""``yaseer report``: one self-contained page, checked as written and in a real headless browser.

References: the golden rows of Example 1 (tests/golden), the errata file (listings/ERRATA.md)
for the slips the page must list, and Debian's chromium for what a reader sees: no console
errors, a player whose frame advances, a screenshot that is not blank.
"""

import csv
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LISTINGS = ROOT / "listings"
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed "
                                    "(Debian: apt-get install chromium); the page's browser checks need it")


def report(tmp_path, *args):
    out = tmp_path / "page.html"
    done = subprocess.run([sys.executable, "-m", "yaseer", "report", *map(str, args), "--out", str(out)],
                          capture_output=True, text=True, cwd=ROOT, timeout=300)
    return done, out


@pytest.fixture(scope="module")
def example1(tmp_path_factory):
    done, page = report(tmp_path_factory.mktemp("report"), LISTINGS / "example1.bas")
    assert done.returncode == 0, done.stderr
    return page


def test_the_page_is_self_contained(example1):
    text = example1.read_text()
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:|//)""", text)
    assert "<link" not in text and "@import" not in text and not re.search(r"url\((?!#)", text)  # only #ids
    assert "@font-face" not in text


def test_the_page_holds_listing_rows_plot_player_and_errata(example1):
    text = example1.read_text()
    assert "60 PRINT USING &quot;#######.##&quot;; QQ; Y(2); V(4); A(36): NEXT QQ" in text  # the listing
    with open(ROOT / "tests" / "golden" / "example1.csv") as handle:
        first = next(csv.reader(handle))
    cells = re.search(r'<table class="rows">.*?<tbody><tr>(.*?)</tr>', text, re.S).group(1)
    values = [float(v) for v in re.findall(r"<td>([^<]*)</td>", cells)]
    assert values == [pytest.approx(float(v), rel=1e-6) for v in first]
    assert "<th>position of piston D, Y(2) (mm)</th>" in text
    assert text.count("<svg") >= 1 and 'class="yaseer-player"' in text
    assert "Errata: Example 1" in text
    errata = (LISTINGS / "ERRATA.md").read_text()
    assert "###.###.##" in errata and "<code>USING &quot;###.###.##&quot;</code>" in text
    assert "Example 2" not in text.split("Errata: Example 1")[1]  # only the errata that apply


def test_a_listing_that_fails_gets_its_page_with_the_error_in_red(tmp_path):
    done, page = report(tmp_path, LISTINGS / "paper" / "example4.bas")
    assert done.returncode == 1 and done.stderr == "Syntax error in 4080\n"
    text = page.read_text()
    assert '<p class="error" id="error">Syntax error in 4080</p>' in text
    assert "Errata: Example 4" in text and "<code>LPRINT USING &quot;#####.#&quot;:QQ; …</code>" in text
    missing, _ = report(tmp_path, tmp_path / "nothing.bas")
    assert missing.returncode == 1 and missing.stderr.startswith("File not found")


def chromium(page: Path, tmp_path: Path, *flags) -> subprocess.CompletedProcess:
    command = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", f"--user-data-dir={tmp_path / 'profile'}",
               "--enable-logging=stderr", "--v=0", *flags, page.as_uri()]
    return subprocess.run(command, capture_output=True, text=True, timeout=120)


def console_messages(log: str) -> list[str]:
    return [line for line in log.splitlines() if ":CONSOLE" in line]


@needs_chromium
def test_in_chromium_no_console_errors_and_the_player_advances(example1, tmp_path):
    broken = tmp_path / "broken.html"
    broken.write_text('<html><body><script>undefinedFunction();</script></body></html>')
    assert console_messages(chromium(broken, tmp_path, "--dump-dom").stderr)  # the check can fail
    done = chromium(example1, tmp_path, "--virtual-time-budget=2000", "--dump-dom")
    assert console_messages(done.stderr) == []
    shown = [int(n) for n in re.findall(r'class="yaseer-player" id="[^"]+" [^>]*data-frame="(\d+)"', done.stdout)]
    assert len(shown) == 1 and shown[0] > 0  # 2 s at 6 frames a second: it moved on from frame 0


@needs_chromium
def test_in_chromium_a_screenshot_is_not_blank(example1, tmp_path):
    from PIL import Image

    shot = tmp_path / "shot.png"
    chromium(example1, tmp_path, "--hide-scrollbars", "--window-size=1280,2400", "--virtual-time-budget=1000",
             f"--screenshot={shot}")
    with Image.open(shot) as image:
        grey = image.convert("L")
        dark = sum(grey.histogram()[:128])
        assert image.size == (1280, 2400)
        assert dark > 0.005 * 1280 * 2400  # text, table, plot: not an empty white page
        assert len(image.convert("RGB").getcolors(1 << 20)) > 50


def test_a_program_that_draws_gets_its_lcd_on_the_page(tmp_path):
    listing = tmp_path / "lcd.bas"
    listing.write_text('10 CLS: PRINT "REPORT";\n20 LOCATE 2,1: PRINT "SHOWN";CHR$(231);\n')
    done, page = report(tmp_path, listing)
    assert done.returncode == 0, done.stderr
    text = page.read_text()
    assert '<h2>The LCD</h2>' in text and "REPORT" in text and "  SHOWNπ" in text
