"""Progress and cancellation on every long call (solve, sweep, batch, coefficients, frf, rotor): the callback
sees fractions that never decrease and end at 1; a callback returning False stops the call with
`tiltpad.Cancelled`, whose message says the callback cancelled it; a `CancelToken` does the same and says so.
"""

from __future__ import annotations

import threading

import pytest

import tiltpad
from conftest import CASES

COMPRESSOR = str(CASES / "compressor-bearing.toml")
RIG = str(CASES / "test-rig-pub5.toml")
ROTOR = str(CASES / "rotors" / "compressor-rotor.toml")


def preview(path: str) -> tiltpad.Case:
    case = tiltpad.load_case(path)
    case.set("mesh.fidelity", "preview")
    return case


# Each long call, with small arguments; `progress` and `cancel` are passed by the test.
CALLS = {
    "solve": lambda **kw: tiltpad.solve(preview(COMPRESSOR), **kw),
    "sweep": lambda **kw: tiltpad.sweep(preview(COMPRESSOR), {"operating.speed_rpm": [6000, 8000, 10000]},
                                        as_frame=False, **kw),
    "batch": lambda **kw: tiltpad.batch(preview(COMPRESSOR), {"bearing.pads.preload": [0.2, 0.3, 0.4, 0.5]},
                                        workers=2, as_frame=False, **kw),
    "coefficients": lambda **kw: tiltpad.coefficients(preview(COMPRESSOR), speeds_rpm=[6000, 9000, 12000],
                                                      refine=True, **kw),
    "frf": lambda **kw: tiltpad.frf(preview(RIG), from_hz=1.0, to_hz=500.0, points=60, **kw),
    "rotor": lambda **kw: tiltpad.rotor(ROTOR, speeds_rpm=[7000, 8500, 10000], coefficients="reduced", **kw),
}


@pytest.mark.parametrize("name", list(CALLS))
def test_progress_increases_to_one(name):
    seen = []
    CALLS[name](progress=lambda f, m: seen.append((f, m)))
    fractions = [f for f, _ in seen]
    assert len(fractions) >= 3, seen
    assert all(b >= a for a, b in zip(fractions, fractions[1:])), fractions
    assert 0.0 < fractions[0] < 1.0, fractions
    assert fractions[-1] == 1.0 and fractions.count(1.0) <= 2, fractions
    assert all(isinstance(m, str) and m for _, m in seen)


@pytest.mark.parametrize("name", list(CALLS))
def test_a_callback_returning_false_cancels(name):
    calls = []

    def stop(f, m):
        calls.append(f)
        return False

    with pytest.raises(tiltpad.Cancelled, match="cancelled.*the progress callback returned False") as info:
        CALLS[name](progress=stop)
    # The call stops at the first report (two threads of a batch may each finish the point they were on).
    assert 1 <= len(calls) <= (2 if name == "batch" else 1), calls
    assert calls[0] < 1.0
    assert info.value.kind == "cancelled" and info.value.details == {"by": "the progress callback returned False"}


@pytest.mark.parametrize("name", list(CALLS))
def test_a_cancel_token_cancels_and_says_so(name):
    token = tiltpad.CancelToken()
    calls = []

    def progress(f, m):
        calls.append(f)
        token.cancel()

    with pytest.raises(tiltpad.Cancelled, match="its CancelToken was cancelled"):
        CALLS[name](progress=progress, cancel=token)
    assert token.cancelled and 1 <= len(calls) <= 2


def test_frf_cancelled_from_another_thread_while_sweeping_the_band():
    """A token set from another thread during the band (after the stages) stops the FRF before the next part of the band."""
    token = tiltpad.CancelToken()
    seen = []
    halfway, cancelled = threading.Event(), threading.Event()

    def progress(f, m):
        seen.append(f)
        if f > 0.9 and not halfway.is_set():
            halfway.set()
            assert cancelled.wait(10.0), "the other thread did not cancel"

    def cancel_when_halfway():
        halfway.wait(60.0)
        token.cancel()
        cancelled.set()

    t = threading.Thread(target=cancel_when_halfway)
    t.start()
    with pytest.raises(tiltpad.Cancelled, match="its CancelToken was cancelled"):
        tiltpad.frf(preview(RIG), from_hz=1.0, to_hz=500.0, points=200, progress=progress, cancel=token)
    t.join()
    # Stopped after the first part of the band (of twenty; the stages report up to 0.9), not at its end.
    assert 0.9 < seen[-1] < 0.91, seen
