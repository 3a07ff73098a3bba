"""Long calls release the GIL, report progress, and stop on Ctrl-C or when the callable says so."""
import _thread
import threading

import numpy as np
import pytest

import tessera


@pytest.fixture(scope="module")
def big_model():
    return tessera.PatchModel(tessera.exemplar("rock", 96, 96, seed=3), patch_width=16, patch_height=16, overlap=4)


def test_progress_reports_fractions(big_model):
    seen = []
    big_model.synthesize(512, 512, seed=1, threads=1, progress=seen.append)
    assert seen and seen == sorted(seen) and 0 <= seen[0] and seen[-1] == pytest.approx(1.0)


def test_two_threads_overlap_inside_cpp(big_model):
    """Thread A's progress callable runs while thread B is inside C++ (not in its own callable).

    Without the GIL released no Python code of another thread can run while B is in C++, so an
    observation of B's state "cpp" from A's callable proves the release (no timing assertion)."""
    for _ in range(20):
        state = {"b": "idle"}
        overlaps = []

        def a_progress(_f):
            if state["b"] == "cpp":
                overlaps.append(True)

        def b_progress(_f):
            state["b"] = "python"
            state["b"] = "cpp"

        def run_b():
            state["b"] = "cpp"
            big_model.synthesize(768, 768, seed=2, threads=1, progress=b_progress)
            state["b"] = "done"

        tb = threading.Thread(target=run_b)
        tb.start()
        big_model.synthesize(768, 768, seed=3, threads=1, progress=a_progress)
        tb.join()
        if overlaps:
            return
    pytest.fail("no progress callable of one thread ever ran while the other was inside C++")


def test_callable_returning_false_cancels(big_model):
    with pytest.raises(tessera.Cancelled):
        big_model.synthesize(512, 512, threads=1, progress=lambda f: False)


def test_callable_exception_propagates(big_model):
    def boom(_f):
        raise LookupError("stop here")

    with pytest.raises(LookupError, match="stop here"):
        big_model.synthesize(512, 512, threads=1, progress=boom)
    with pytest.raises(TypeError, match="progress must be a callable"):
        big_model.synthesize(16, 16, progress=42)


def test_keyboard_interrupt_stops_the_work(big_model):
    calls = []

    def progress(f):
        calls.append(f)
        if len(calls) == 1:  # Ctrl-C from another thread while the C++ work runs
            threading.Thread(target=_thread.interrupt_main).start()

    with pytest.raises(KeyboardInterrupt):
        big_model.synthesize(2048, 2048, threads=1, progress=progress)
    assert calls[-1] < 1.0  # stopped early
    # the module still works afterwards
    assert big_model.synthesize(8, 8).shape == (8, 8, 3)


def test_model_build_is_cancellable():
    ex = tessera.exemplar("sand", 64, 64)
    with pytest.raises(tessera.Cancelled):
        tessera.PatchModel(ex, progress=lambda f: False)
    m = tessera.PatchModel(ex, patch_width=12, patch_height=12, overlap=3, threads=2)
    np.testing.assert_array_equal(m.synthesize(40, 40, seed=4, threads=2), m.synthesize(40, 40, seed=4, threads=1))
