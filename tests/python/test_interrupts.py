"""Ctrl-C stops a run with KeyboardInterrupt and leaves nothing behind; a progress callable that
says stop, or raises, stops it too; Python's own Ctrl-C handling is back afterwards."""

import os
import signal

import numpy as np
import pytest

import terrain_sketch
from conftest import SAMPLE


def earlier_output(tmp_path):
    path = tmp_path / "strokes.geojson"
    path.write_text("the earlier run's")
    return path


def test_ctrl_c_raises_keyboard_interrupt_and_keeps_the_earlier_output(tmp_path):
    path = earlier_output(tmp_path)
    calls = []

    def press_ctrl_c(fraction):
        calls.append(fraction)
        if len(calls) == 1:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        terrain_sketch.silhouettes(SAMPLE, path, azimuth=200, preview=tmp_path / "p.svg",
                                   progress=press_ctrl_c)
    assert path.read_text() == "the earlier run's"
    assert sorted(os.listdir(tmp_path)) == ["strokes.geojson"]  # no staging left, no preview
    # Python's handler is back: Ctrl-C now interrupts Python itself.
    with pytest.raises(KeyboardInterrupt):
        os.kill(os.getpid(), signal.SIGINT)
        for _ in range(1000):
            pass
    # And the next run is not taken for interrupted.
    assert terrain_sketch.silhouettes(SAMPLE, path, azimuth=200)["factual_strokes"] > 0


def test_ctrl_c_stops_a_sketch_of_an_array():
    heights = np.random.default_rng(1).random((600, 500), dtype=np.float32) * 300

    def press_ctrl_c(_fraction):
        os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        terrain_sketch.sketch(heights, (0, 30, 0, 0, 0, -30), crs="EPSG:32632",
                              progress=press_ctrl_c)


def test_progress_saying_stop_raises_cancelled(tmp_path):
    path = earlier_output(tmp_path)
    seen = {}  # each run's fractions

    def stop_at_a_third(run):
        def progress(fraction):
            seen.setdefault(run, []).append(fraction)
            return fraction < 0.3
        return progress

    with pytest.raises(terrain_sketch.Cancelled):
        terrain_sketch.classify(SAMPLE, tmp_path / "c.tif", progress=stop_at_a_third("classify"))
    with pytest.raises(terrain_sketch.Cancelled):
        terrain_sketch.silhouettes(SAMPLE, path, progress=stop_at_a_third("silhouettes"))
    assert path.read_text() == "the earlier run's"
    assert sorted(os.listdir(tmp_path)) == ["strokes.geojson"]
    assert sorted(seen) == ["classify", "silhouettes"]
    for fractions in seen.values():
        assert fractions == sorted(fractions) and all(0 <= f <= 1 for f in fractions)
        # It stopped at the first fraction of a third or more.
        assert fractions[-1] >= 0.3 and all(f < 0.3 for f in fractions[:-1])


def test_progress_raising_stops_the_run_with_its_exception(tmp_path):
    def fail(_fraction):
        raise ZeroDivisionError("the caller's own")

    with pytest.raises(ZeroDivisionError, match="the caller's own"):
        terrain_sketch.silhouettes(SAMPLE, tmp_path / "s.gpkg", progress=fail)
    assert not os.listdir(tmp_path)


def test_progress_reaches_the_end(tmp_path):
    seen = []
    terrain_sketch.silhouettes(SAMPLE, tmp_path / "s.gpkg", progress=seen.append)
    assert seen and seen[-1] == pytest.approx(1.0) and seen == sorted(seen)
