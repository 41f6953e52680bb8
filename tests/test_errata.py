"""The errata a report shows: the rows and section of listings/ERRATA.md that apply to one example."""

from pathlib import Path

from yaseer.errata import errata_for, example_number, to_html

ROOT = Path(__file__).resolve().parents[1]
ERRATA = (ROOT / "listings" / "ERRATA.md").read_text()


def test_the_summary_rows_of_the_example_and_program_5_only_when_it_is_loaded():
    summary = ERRATA.split("## Summary")[1].split("\n## ")[0]
    for n in range(1, 6):
        expected = [line for line in summary.splitlines() if line.startswith(f"| {n} |")]
        for listing in (ROOT / "listings" / f"example{n}.bas", ROOT / "listings" / "paper" / f"example{n}.bas"):
            found = errata_for(listing)
            assert found.example == n and found.summary == expected and expected
            assert found.section.splitlines()[0].startswith("| line | printed | corrected | reason |")
            assert "| 2 | only in Example 1 | added to Examples 2–5 |" in found.all_examples
    with_prog5 = errata_for(ROOT / "listings" / "example1.bas", printed_program_5=True)
    assert with_prog5.summary[-1].startswith("| Program 5 | 60 |")
    assert errata_for(ROOT / "listings" / "fortran_fourbar.bas") is None
    assert example_number("example3") == 3 and example_number("example") is None


def test_markdown_tables_lists_code_and_emphasis_become_html():
    page = to_html("A `PRINT` *on* it\n\n- one\n  more\n- two\n\n| a | b |\n|---|---|\n| 1 | `x<y` |")
    assert page == ("<p>A <code>PRINT</code> <em>on</em> it</p>\n<ul><li>one more</li><li>two</li></ul>\n"
                    "<table><thead><tr><th>a</th><th>b</th></tr></thead>"
                    "<tbody><tr><td>1</td><td><code>x&lt;y</code></td></tr></tbody></table>")
