"""yaseer.progress: a bar only for work that lasts, only on stderr (or the stream given)."""

from __future__ import annotations

import io

from yaseer.progress import bar, track


class Terminal(io.StringIO):
    def isatty(self):
        return True


def test_a_short_task_shows_no_bar():
    stream = Terminal()
    with bar(3, "quick", file=stream, delay=3600.0) as progress:
        progress.update(3)
    assert stream.getvalue() == ""


def test_a_task_past_its_delay_shows_counts_on_the_stream():
    stream = Terminal()
    items = list(track(range(4), description="frames", file=stream, delay=0.0, refresh_seconds=0.0))
    assert items == [0, 1, 2, 3]
    assert "frames" in stream.getvalue() and "4/4" in stream.getvalue()


def test_no_bar_on_a_stream_that_is_not_a_terminal_unless_forced():
    redirected = io.StringIO()
    with bar(2, file=redirected, delay=0.0, refresh_seconds=0.0) as progress:
        progress.update(2)
    assert redirected.getvalue() == ""
    with bar(2, file=redirected, delay=0.0, force=True, refresh_seconds=0.0) as progress:
        progress.update(2)
    assert "2/2" in redirected.getvalue()


def test_unknown_totals_count_up():
    stream = Terminal()
    with bar(None, "running", "line", file=stream, delay=0.0, refresh_seconds=0.0) as progress:
        progress.update(5)
    assert "5line" in stream.getvalue().replace(" ", "")


def test_program_output_to_a_file_is_counted_on_the_terminal():
    from yaseer.progress import output_progress

    output, terminal = io.StringIO(), Terminal()
    with output_progress(output, file=terminal, delay=0.0, refresh_seconds=0.0) as stream:
        stream.write(" 1 \n 2 \n")
        stream.write(" 3 \n")
    assert output.getvalue() == " 1 \n 2 \n 3 \n"  # the output itself is untouched
    assert "3line" in terminal.getvalue().replace(" ", "")
    assert "1 \n" not in terminal.getvalue()


def test_program_output_to_the_terminal_gets_no_bar():
    from yaseer.progress import output_progress

    screen = Terminal()
    with output_progress(screen, delay=0.0, refresh_seconds=0.0) as stream:
        assert stream is screen
        stream.write("row\n")
    assert screen.getvalue() == "row\n"
