#!/usr/bin/env python3
"""Tables and plot of the powerwall scaling experiment (launch/scaling; docs/BENCHMARKS.md).

Input: the runs.csv written by launch/scaling (one line per rank count: the GPU grid, the tile
size, the warm-up frames, the --stats CSV of that run and the other load on the machine). Every stats CSV has, per frame, the
master's wall-clock frame time and, per rank, prepare_ms, render_ms, render_cpu_ms, wait_ms and
swap_ms (src/cluster/frame_stats.h). Frames before the warm-up count are left out.

Two sets of numbers:

* Wall clock, as measured here: frame_ms on the master (broadcast to after the report gather).
  With more ranks than cores this measures how the machine time-slices the ranks, not the program.
* Modelled, for N dedicated one-core nodes (each rank renders with LP_NUM_THREADS=1, so its
  llvmpipe work is one thread and its process CPU time is its time on a core of its own):

      modelled frame = max over ranks (prepare + render_cpu) + comm

  prepare is the per-frame CPU work every rank repeats (the curtain map; it depends only on the
  animation time). The stats give it as wall time only, which time-slicing inflates, so we take
  the least disturbed measurement of the same work: the minimum prepare_ms over every rank of
  every run at the same animation time. comm is the communication on the critical path
  (broadcast + swap barrier + report gather), see sync below, measured where every rank had a
  core of its own (N <= cores), in the frame where it was smallest (other processes can only
  delay a rank, never speed the messages up); for larger N it is the largest such measurement scaled by the
  depth of a binomial tree, ceil(log2 N) / ceil(log2 N_measured), as Open MPI's broadcast,
  barrier and gather are trees. (This is shared memory, not a network: an InfiniBand or Ethernet
  hop costs 2-50 us, still far below the frame time.)

Per-frame definitions (ms):
  sync        = frame_ms - max_r(prepare_r + render_r) - max_r(swap_r): everything on the
                master's frame that is not work: broadcast, barrier, gather, bookkeeping
  barrier     = min_r wait_r: the last rank to reach the swap barrier waits only for the barrier
                itself (every other rank also waits for it: that excess is imbalance)
  imbalance wait = mean_r(wait_r) - barrier: the time ranks idle for the slowest one
  imbalance   = max_r render_cpu_r / mean_r render_cpu_r (CPU time: unaffected by time-slicing)
Speedup is the pixel rate over the 1-rank pixel rate, as in the paper (each GPU keeps its
1680x2100 pixels: 10 GPUs at 29 fps against 1 at 35 fps is 10 x 29 / 35 = 8.3, the paper's 8.2);
parallel efficiency = speedup / N.

Usage: scaling-model.py RUNS.csv [--cores N] [--plot FILE.png]
"""
import argparse
import csv
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

# The MPIglut paper's published powerwall table: GPUs -> (resolution, fps, speedup).
PAPER = {
    1: ("1680x2100", 35, 1.0),
    2: ("3360x2100", 30, 1.6),
    4: ("6720x2100", 27, 3.0),
    8: ("6720x4200", 29, 6.5),
    10: ("8400x4200", 29, 8.2),
}
PHASES = ("prepare_ms", "render_ms", "render_cpu_ms", "wait_ms", "swap_ms")


def read_stats(path, warmup):
    """Frames after the warm-up: dicts with frame_ms, time_s, pixels and ranks (one dict of PHASES each)."""
    frames = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if int(row["frame"]) < warmup:
                continue
            count = sum(1 for key in row if key.startswith("render_cpu_ms_rank"))
            frame_ms = float(row["frame_ms"])
            frames.append({
                "time_s": float(row["time_s"]),
                "frame_ms": frame_ms,
                "pixels": float(row["mpixel_per_s"]) * frame_ms * 1e3,
                "ranks": [dict({p: float(row[f"{p}_rank{r}"]) for p in PHASES},
                               # Load balancing moves band pixels between ranks (0 for the static split).
                               exchange_mb=float(row.get(f"exchange_mb_rank{r}") or 0.0),
                               # ... and measures each rank's drawn work (0: not measured).
                               render_work=float(row.get(f"render_work_rank{r}") or 0.0)) for r in range(count)],
            })
    if not frames:
        sys.exit(f"scaling-model: {path} has no frames after the {warmup} warm-up frame(s)")
    return frames


def read_runs(runs_csv):
    folder = os.path.dirname(os.path.abspath(runs_csv))
    runs = []
    with open(runs_csv, newline="") as f:
        for row in csv.DictReader(f):
            run = {key: int(row[key]) for key in ("ranks", "gpu_columns", "gpu_rows", "tile_width_px", "tile_height_px")}
            run["frames"] = read_stats(os.path.join(folder, row["stats"]), int(row["warmup"]))
            # Cores' worth of CPU other processes used during the run (launch/scaling measures it).
            run["other_load"] = row.get("other_load_cores") or "-"
            runs.append(run)
    return sorted(runs, key=lambda run: run["ranks"])


def tree_depth(n):
    return max(1, math.ceil(math.log2(n))) if n > 1 else 1


def analyse(runs, cores, bandwidth_gb_s=1.25):
    """Adds the per-run summary (means over the measured frames) to every run; returns the runs."""
    # The least disturbed measurement of each animation time's prepare work, over all runs.
    prepare = {}
    for run in runs:
        for fr in run["frames"]:
            key = round(fr["time_s"], 6)
            prepare[key] = min([prepare.get(key, math.inf)] + [r["prepare_ms"] for r in fr["ranks"]])

    for run in runs:
        per_frame = []
        for fr in run["frames"]:
            ranks = fr["ranks"]
            cpu = [r["render_cpu_ms"] for r in ranks]
            barrier = min(r["wait_ms"] for r in ranks)
            per_frame.append({
                "frame_ms": fr["frame_ms"],
                "pixels": fr["pixels"],
                "prepare": prepare[round(fr["time_s"], 6)],
                "work_cpu": prepare[round(fr["time_s"], 6)] + max(cpu),
                "render_cpu_max": max(cpu),
                "render_cpu_mean": statistics.fmean(cpu),
                "imbalance": max(cpu) / statistics.fmean(cpu) if statistics.fmean(cpu) > 0 else 1.0,
                # The same for the rays' work each rank drew (free of timing noise), where measured.
                "work_imbalance": (max(work) / statistics.fmean(work) if min(work) > 0 else math.nan)
                                  if (work := [r["render_work"] for r in ranks]) else math.nan,
                "sync": fr["frame_ms"] - max(r["prepare_ms"] + r["render_ms"] for r in ranks) - max(r["swap_ms"] for r in ranks),
                "barrier": barrier,
                "exchange_mb_max": max(r["exchange_mb"] for r in ranks),
                "imbalance_wait": statistics.fmean(r["wait_ms"] for r in ranks) - barrier,
            })
        run["mean"] = {key: statistics.fmean(f[key] for f in per_frame) for key in per_frame[0]}
        # The communication itself is the same every frame; what varies is other processes
        # delaying a rank: the least disturbed frame measures it.
        run["mean"]["sync_min"] = min(f["sync"] for f in per_frame)
        run["rank_cpu"] = [statistics.fmean(fr["ranks"][r]["render_cpu_ms"] for fr in run["frames"])
                           for r in range(run["ranks"])]

    measured = [run for run in runs if run["ranks"] <= cores]
    if not measured:
        sys.exit(f"scaling-model: no run has at most {cores} ranks: the communication cost cannot be measured")
    reference = max(measured, key=lambda run: run["ranks"])
    for run in runs:
        m = run["mean"]
        if run["ranks"] <= cores:
            m["comm"], m["comm_source"] = m["sync_min"], "measured"
        else:
            m["comm"] = reference["mean"]["sync_min"] * tree_depth(run["ranks"]) / tree_depth(reference["ranks"])
            m["comm_source"] = f"{reference['ranks']}-rank x {tree_depth(run['ranks'])}/{tree_depth(reference['ranks'])}"
        # Band pixels of the load balancer cross the network: the busiest rank's megabytes (as sent:
        # compressed, io/band_compression.h) at the link bandwidth (this machine's shared memory
        # would be far faster; a cluster's network is not).
        m["exchange"] = m["exchange_mb_max"] / bandwidth_gb_s
        m["modelled_ms"] = m["work_cpu"] + m["comm"] + m["exchange"]
        m["fps_wall"] = 1e3 / m["frame_ms"]
        m["fps_model"] = 1e3 / m["modelled_ms"]
        m["mpix_wall"] = m["pixels"] * m["fps_wall"] / 1e6
        m["mpix_model"] = m["pixels"] * m["fps_model"] / 1e6

    base = runs[0]["mean"]
    for run in runs:
        m = run["mean"]
        m["speedup_wall"] = m["mpix_wall"] / base["mpix_wall"]
        m["speedup_model"] = m["mpix_model"] / base["mpix_model"]
        m["efficiency_wall"] = m["speedup_wall"] / run["ranks"]
        m["efficiency_model"] = m["speedup_model"] / run["ranks"]
    return runs


def table(header, rows):
    widths = [max(len(str(x)) for x in column) for column in zip(header, *rows)]
    line = lambda cells: "| " + " | ".join(str(c).rjust(w) for c, w in zip(cells, widths)) + " |"
    return "\n".join([line(header), "|" + "|".join("-" * (w + 2) for w in widths) + "|"] + [line(r) for r in rows])


def report(runs, cores):
    out = []
    tile = f"{runs[0]['tile_width_px']}x{runs[0]['tile_height_px']}"
    frames = len(runs[0]["frames"])
    out.append(f"Paper (MPIglut, GPUs, 1680x2100 per GPU) beside ours ({tile} per rank, {frames} measured frames, "
               f"{cores} cores; modelled = N dedicated 1-core nodes)\n")
    rows = []
    for run in runs:
        n, m = run["ranks"], run["mean"]
        res, fps, speedup = PAPER.get(n, ("-", "-", "-"))
        ours = f"{run['gpu_columns'] * run['tile_width_px']}x{run['gpu_rows'] * run['tile_height_px']}"
        paper_mpix = "-" if res == "-" else f"{math.prod(map(int, res.split('x'))) * fps / 1e6:.0f}"
        rows.append([n, res, fps, speedup, paper_mpix, ours, f"{m['fps_model']:.2f}", f"{m['speedup_model']:.2f}",
                     f"{m['efficiency_model']:.0%}", f"{m['mpix_model']:.3f}", f"{m['fps_wall']:.2f}",
                     f"{m['speedup_wall']:.2f}", f"{m['efficiency_wall']:.0%}", f"{m['mpix_wall']:.3f}"])
    out.append(table(["GPUs", "paper res", "paper fps", "paper speedup", "paper Mpix/s", "our res",
                      "model fps", "model speedup", "model eff", "model Mpix/s",
                      "wall fps", "wall speedup", "wall eff", "wall Mpix/s"], rows))

    out.append("\nWhere the time goes (ms per frame, means over the measured frames)\n")
    rows = []
    for run in runs:
        m = run["mean"]
        rows.append([run["ranks"], f"{m['prepare']:.1f}", f"{m['render_cpu_max']:.1f}", f"{m['render_cpu_mean']:.1f}",
                     f"{m['imbalance']:.2f}", "-" if math.isnan(m["work_imbalance"]) else f"{m['work_imbalance']:.3f}",
                     f"{m['comm']:.3f}", m["comm_source"], f"{m['exchange']:.2f}",
                     f"{m['modelled_ms']:.1f}",
                     f"{m['frame_ms']:.1f}", f"{m['sync']:.3f}", f"{m['barrier']:.3f}", f"{m['imbalance_wait']:.1f}"])
    out.append(table(["ranks", "prepare", "render cpu max", "render cpu mean", "imbalance", "work imbalance", "comm", "comm from", "exchange",
                      "modelled frame", "wall frame", "wall sync", "wall barrier", "wall imbalance wait"], rows))

    out.append(f"\nModel check where every rank has a core of its own (ranks <= {cores} cores)\n")
    rows = []
    for run in runs:
        if run["ranks"] <= cores:
            m = run["mean"]
            rows.append([run["ranks"], f"{m['frame_ms']:.1f}", f"{m['modelled_ms']:.1f}",
                         f"{(m['modelled_ms'] - m['frame_ms']) / m['frame_ms']:+.1%}", run["other_load"]])
    out.append(table(["ranks", "wall-clock frame", "modelled frame", "model - wall", "other load (cores)"], rows))

    out.append("\nMean render CPU time per rank (ms), laid out as the wall (rank 0 top left)\n")
    for run in runs:
        cols = run["gpu_columns"]
        cpu = run["rank_cpu"]
        out.append(f"{run['ranks']} rank(s):")
        for row in range(run["gpu_rows"]):
            out.append("  " + " ".join(f"{cpu[row * cols + c]:8.1f}" for c in range(cols)))
    return "\n".join(out)


def plot(runs, path):
    """Speedup against ranks with gnuplot: ours modelled and wall-clock, the paper's, the ideal line."""
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print(f"scaling-model: gnuplot not found, no plot ({path}); install it with: apt-get install gnuplot-nox",
              file=sys.stderr)
        return
    largest = max(max(run["ranks"] for run in runs), max(PAPER))
    with tempfile.TemporaryDirectory() as folder:
        ours = os.path.join(folder, "ours.dat")
        paper = os.path.join(folder, "paper.dat")
        with open(ours, "w") as f:
            for run in runs:
                f.write(f"{run['ranks']} {run['mean']['speedup_model']} {run['mean']['speedup_wall']}\n")
        with open(paper, "w") as f:
            for n, (_, _, speedup) in sorted(PAPER.items()):
                f.write(f"{n} {speedup}\n")
        script = f"""
set terminal pngcairo size 800,560 font ",11"
set output "{path}"
set title "Powerwall scaling: speedup (pixel rate over 1 rank)"
set xlabel "ranks (GPUs in the paper)"
set ylabel "speedup"
set xrange [0:{largest + 1}]
set yrange [0:{largest + 1}]
set key top left
set grid
plot x title "ideal" with lines dashtype 2 linecolor rgb "gray40", \\
     "{paper}" using 1:2 title "MPIglut paper (GPUs)" with linespoints pointtype 7 pointsize 1.4 linecolor rgb "black", \\
     "{ours}" using 1:2 title "ours, modelled (N dedicated 1-core nodes)" with linespoints pointtype 5 linecolor rgb "#1f77b4", \\
     "{ours}" using 1:3 title "ours, wall clock on this machine" with linespoints pointtype 9 linecolor rgb "#d62728"
"""
        subprocess.run([gnuplot], input=script, text=True, check=True)
    print(f"\nwrote {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", help="runs.csv written by launch/scaling")
    parser.add_argument("--cores", type=int, default=os.cpu_count(), help="cores of the machine that ran it (default: this one's)")
    parser.add_argument("--plot", help="write the speedup plot to this PNG (gnuplot)")
    parser.add_argument("--bandwidth-gb-s", type=float, default=1.25,
                        help="network bandwidth of the modelled cluster for load-balanced band pixels, GB/s "
                             "(default 1.25: 10 Gigabit Ethernet)")
    args = parser.parse_args()
    runs = analyse(read_runs(args.runs), args.cores, args.bandwidth_gb_s)
    print(report(runs, args.cores))
    if args.plot:
        plot(runs, args.plot)


if __name__ == "__main__":
    main()
