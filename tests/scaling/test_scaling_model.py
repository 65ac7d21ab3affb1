#!/usr/bin/env python3
"""Tests of launch/scaling-model.py on a hand-computed synthetic experiment, and of the committed
full-size walls against launch/scaling's generator. Usage: test_scaling_model.py SOURCE_DIR"""
import filecmp
import importlib.util
import math
import os
import subprocess
import sys
import tempfile
import unittest

SOURCE = os.path.abspath(sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "../.."))
spec = importlib.util.spec_from_file_location("scaling_model", os.path.join(SOURCE, "launch/scaling-model.py"))
model = importlib.util.module_from_spec(spec)
spec.loader.exec_module(model)

TILE_PIXELS = 10 * 20

# Per run: frames as (time_s, frame_ms, [(prepare, render, render_cpu, wait, swap) per rank]).
# Frame 0 is warm-up junk the model must ignore.
WARMUP_JUNK = (0.0, 9999.0, None)
RUNS = {
    1: [(1.0, 111.0, [(10, 100, 100, 0.5, 0)]),
        (2.0, 123.0, [(12, 110, 108, 0.5, 0)])],
    2: [(1.0, 132.0, [(11, 100, 100, 20.5, 0), (10, 120, 120, 0.5, 0)]),
        (2.0, 124.0, [(12, 110, 110, 0.5, 0), (13, 90, 90, 20.5, 0)])],
    # More ranks than cores: wall times inflated by time-slicing, CPU times not.
    4: [(1.0, 500.0, [(30, 400, 100, 0, 0)] * 3 + [(30, 400, 140, 0, 0)]),
        (2.0, 500.0, [(30, 400, 100, 0, 0)] * 4)],
}
GRID = {1: (1, 1), 2: (2, 1), 4: (4, 1)}


def write_experiment(folder):
    with open(os.path.join(folder, "runs.csv"), "w") as runs:
        runs.write("ranks,gpu_columns,gpu_rows,tile_width_px,tile_height_px,warmup,stats\n")
        for n, frames in RUNS.items():
            runs.write(f"{n},{GRID[n][0]},{GRID[n][1]},10,20,1,s{n}.csv\n")
            with open(os.path.join(folder, f"s{n}.csv"), "w") as f:
                f.write("frame,time_s,frame_ms,fps,mpixel_per_s,render_max_ms,render_mean_ms,imbalance")
                for r in range(n):
                    f.write("".join(f",{c}_rank{r}" for c in
                                    ("frame", "time_s", "prepare_ms", "render_ms", "render_cpu_ms", "wait_ms", "swap_ms")))
                f.write("\n")
                for index, (time_s, frame_ms, ranks) in enumerate([WARMUP_JUNK] + frames):
                    ranks = ranks or [(999, 999, 999, 999, 999)] * n
                    mpix = n * TILE_PIXELS / (frame_ms * 1e3)
                    f.write(f"{index},{time_s},{frame_ms},{1e3 / frame_ms},{mpix},0,0,1")
                    f.write("".join(f",{index},{time_s}," + ",".join(map(str, r)) for r in ranks))
                    f.write("\n")


class ModelTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        write_experiment(cls.folder.name)
        cls.runs = {run["ranks"]: run["mean"] for run in
                    model.analyse(model.read_runs(os.path.join(cls.folder.name, "runs.csv")), cores=2)}

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_prepare_is_the_least_disturbed_measurement_of_each_time(self):
        # t=1: min(10, 11, 10, 30) = 10; t=2: min(12, 12, 13, 30) = 12, in every run.
        for n in RUNS:
            self.assertAlmostEqual(self.runs[n]["prepare"], 11.0)

    def test_sync_barrier_and_imbalance_wait(self):
        # sync = frame - max(prepare + render) - max(swap): 111-110, 123-122; 132-130, 124-122.
        self.assertAlmostEqual(self.runs[1]["sync"], 1.0)
        self.assertAlmostEqual(self.runs[2]["sync"], 2.0)
        self.assertAlmostEqual(self.runs[2]["barrier"], 0.5)  # the last rank's wait
        self.assertAlmostEqual(self.runs[2]["imbalance_wait"], 10.0)  # mean(20.5, 0.5) - 0.5

    def test_modelled_frame(self):
        # 1 rank: mean(10 + 100, 12 + 108) + 1 = 116.
        self.assertAlmostEqual(self.runs[1]["modelled_ms"], 116.0)
        # 2 ranks: mean(10 + 120, 12 + 110) + 2 = 128.
        self.assertAlmostEqual(self.runs[2]["modelled_ms"], 128.0)
        # 4 ranks > 2 cores: comm from the 2-rank run times tree depth 2/1 = 4; mean(10 + 140, 12 + 100) + 4.
        self.assertAlmostEqual(self.runs[4]["comm"], 4.0)
        self.assertAlmostEqual(self.runs[4]["modelled_ms"], 135.0)

    def test_exchanged_band_pixels_cost_their_megabytes_at_the_bandwidth(self):
        # No exchange_mb column (the static split): nothing added.
        self.assertEqual(self.runs[2]["exchange"], 0.0)
        # 12.5 MB moved by the busiest rank at 1.25 GB/s (10 GbE) is 10 ms more per frame.
        runs = model.read_runs(os.path.join(self.folder.name, "runs.csv"))
        for run in runs:
            for frame in run["frames"]:
                for r, rank in enumerate(frame["ranks"]):
                    rank["exchange_mb"] = 12.5 if r == 0 else 1.0
        exchanged = {run["ranks"]: run["mean"] for run in model.analyse(runs, cores=2, bandwidth_gb_s=1.25)}
        self.assertAlmostEqual(exchanged[2]["exchange"], 10.0)
        self.assertAlmostEqual(exchanged[2]["modelled_ms"], self.runs[2]["modelled_ms"] + 10.0)

    def test_speedup_and_efficiency(self):
        self.assertAlmostEqual(self.runs[2]["speedup_model"], 2 * 116 / 128)
        self.assertAlmostEqual(self.runs[2]["efficiency_model"], 116 / 128)
        self.assertAlmostEqual(self.runs[4]["speedup_model"], 4 * 116 / 135)
        self.assertAlmostEqual(self.runs[2]["speedup_wall"], 2 * 117 / 128)  # wall frames 117 and 128
        self.assertAlmostEqual(self.runs[4]["efficiency_wall"], 117 / 500)

    def test_imbalance_uses_cpu_time(self):
        self.assertAlmostEqual(self.runs[4]["imbalance"], (140 / 110 + 1) / 2)
        self.assertAlmostEqual(self.runs[2]["imbalance"], (120 / 110 + 110 / 100) / 2)

    def test_work_imbalance_where_the_work_was_measured(self):
        # No render_work column (the static split): not a number, printed as "-".
        self.assertTrue(math.isnan(self.runs[2]["work_imbalance"]))
        runs = model.read_runs(os.path.join(self.folder.name, "runs.csv"))
        for run in runs:
            for index, frame in enumerate(run["frames"]):
                for r, rank in enumerate(frame["ranks"]):
                    rank["render_work"] = 300.0 if r == 0 and index == 0 else 200.0
        measured = {run["ranks"]: run["mean"] for run in model.analyse(runs, cores=2)}
        self.assertAlmostEqual(measured[2]["work_imbalance"], (300 / 250 + 1) / 2)
        self.assertAlmostEqual(measured[4]["work_imbalance"], (300 / 225 + 1) / 2)

    def test_report_prints_the_papers_numbers_beside_ours(self):
        runs = model.analyse(model.read_runs(os.path.join(self.folder.name, "runs.csv")), cores=2)
        text = model.report(runs, 2)
        self.assertIn("| 3360x2100 |        30 |", text)
        self.assertIn("+0.0%", text.split("Model check")[1])  # 2 ranks: 128 modelled, 128 wall
        self.assertIn("-0.9%", text.split("Model check")[1])  # 1 rank: 116 against 117


class WallsTest(unittest.TestCase):
    def test_committed_walls_are_the_generators_full_size_walls(self):
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([os.path.join(SOURCE, "launch/scaling"), "--dry-run", "--scale", "1", "--out", out],
                           check=True, stdout=subprocess.DEVNULL)
            for n in (1, 2, 4, 8, 10):
                name = f"scaling-{n}.toml"
                self.assertTrue(filecmp.cmp(os.path.join(out, "walls", name),
                                            os.path.join(SOURCE, "config/walls", name), shallow=False), name)


if __name__ == "__main__":
    unittest.main()
