"""``%%basic`` in a real kernel (jupyter_client + ipykernel), as a notebook sends it cells.

What a teacher sees: the screen arrives while the program runs (not all at the end),
``--input "3, 4"`` written as the docs write it answers INPUT with 3 and 4, and a listing
with no header has the same column names in ``rows.names`` as on its plot.
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest

jupyter_client = pytest.importorskip("jupyter_client", reason="the kernel tests need yaseer[jupyter]")
pytest.importorskip("ipykernel", reason="the kernel tests need yaseer[jupyter] (ipykernel)")

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def kernel():
    manager, client = jupyter_client.manager.start_new_kernel(kernel_name="python3", cwd=str(ROOT))
    try:
        execute(client, "%load_ext yaseer")
        yield client
    finally:
        client.stop_channels()
        manager.shutdown_kernel(now=True)


def execute(client, code: str, timeout: float = 120) -> list[tuple[float, dict]]:
    """Run one cell; its output messages (arrival time, message) until the kernel is idle again."""
    msg_id = client.execute(code)
    messages = []
    deadline = time.monotonic() + timeout
    while True:
        message = client.get_iopub_msg(timeout=max(1.0, deadline - time.monotonic()))
        if message["parent_header"].get("msg_id") != msg_id:
            continue
        if message["msg_type"] == "status" and message["content"]["execution_state"] == "idle":
            return messages
        messages.append((time.monotonic(), message))


def stdout(messages) -> str:
    return "".join(m["content"]["text"] for _, m in messages
                   if m["msg_type"] == "stream" and m["content"]["name"] == "stdout")


def results(messages) -> list[str]:
    return [m["content"]["data"]["text/plain"] for _, m in messages if m["msg_type"] == "execute_result"]


def test_the_screen_streams_into_the_cell_while_the_program_runs(kernel):
    # The busy loop lasts about a second or more; its length is not asserted, only the order of
    # arrivals: FIRST reaches the notebook before the loop ends, LAST after.
    cell = ("%%basic\n10 PRINT \"FIRST\"\n20 T = 0: FOR I = 1 TO 4000000: T = T + SIN(I): NEXT I\n"
            "30 PRINT \"LAST\"\n")
    messages = execute(kernel, cell)
    assert stdout(messages) == "FIRST\nLAST\n"
    chunks = [(arrived, m["content"]["text"]) for arrived, m in messages if m["msg_type"] == "stream"]
    first = next(arrived for arrived, text in chunks if "FIRST" in text)
    last = next(arrived for arrived, text in chunks if "LAST" in text)
    assert not any("FIRST" in text and "LAST" in text for _, text in chunks)  # two messages, not one at the end
    assert last - first > 0.2  # the kernel sends its stream every 0.2 s: FIRST went out while the loop ran


@pytest.mark.parametrize("line, answers", [('--input "3, 4"', "3, 4"), ("--input '3, 4'", "3, 4"),
                                           ('--input "3\\n4"', "3\n4"), ("--input 3\\n4", "3\n4")])
def test_input_written_as_the_docs_write_it_answers_input(kernel, line, answers):
    # one line of two answers is GW-BASIC's INPUT A, B (the Casio asks for each variable)
    program = "10 INPUT A, B\n20 PRINT A * B\n" if "," in answers else "10 INPUT A\n15 INPUT B\n20 PRINT A * B\n"
    dialect = " --dialect gw" if "," in answers else ""
    messages = execute(kernel, f"%%basic {line}{dialect}\n{program}")
    echoed = "".join(f"? {answer}\n" for answer in answers.split("\n"))
    assert stdout(messages) == echoed + " 12 \n"
    assert not [m for _, m in messages if m["msg_type"] in ("error", "display_data")]


def test_a_listing_without_a_header_names_its_columns_as_its_plot_does(kernel):
    execute(kernel, "%%basic -o plain\n10 FOR QQ = 0 TO 90 STEP 30: T(2) = QQ: L(2) = 1: L(3) = 3: GOSUB PROG 1\n"
                    "20 PRINT QQ; X(2); V(3): NEXT QQ\n")
    (names,) = results(execute(kernel, "plain.rows.names"))
    assert names == "('QQ', 'X(2)', 'V(3)')"
    (column,) = results(execute(kernel, "[round(float(x), 9) for x in plain.rows.column('X(2)')]"))
    # X(2): the slider of a 1-3 slider-crank on its axis, cos(t) + sqrt(9 - sin(t)^2).
    import math

    expected = [round(math.cos(math.radians(t)) + math.sqrt(9 - math.sin(math.radians(t)) ** 2), 9)
                for t in (0, 30, 60, 90)]
    assert column == repr(expected)
    (labels,) = results(execute(kernel, "[ax.get_ylabel() for ax in plain.plot().axes]"))
    assert labels == "['X(2)', 'V(3)']"
