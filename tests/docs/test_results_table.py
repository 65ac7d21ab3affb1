#!/usr/bin/env python3
"""launch/results-table: a table from a CSV (quoted fields, --where, --columns, --latest), the marked
tables of a guide rewritten by --update and reported by --check, errors; and docs/ in step with
bench/results. usage: test_results_table.py SOURCE_DIR"""
import os
import subprocess
import sys
import tempfile

src = sys.argv[1]
tool = os.path.join(src, "launch", "results-table")
failures = []


def run(*args, cwd=None):
    p = subprocess.run([sys.executable, tool, *args], capture_output=True, text=True, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


def expect(name, got, want):
    if got != want:
        failures.append(f"{name}:\n  got  {got!r}\n  want {want!r}")


with tempfile.TemporaryDirectory() as tmp:
    csv_path = os.path.join(tmp, "runs.csv")
    with open(csv_path, "w") as f:
        f.write("date,machine,method,ms\n"
                '2026-01-01,"vm 2 cores, x86_64",a,1.5\n'
                '2026-01-01,"vm 2 cores, x86_64",b,2.5\n'
                '2026-01-02,"vm 2 cores, x86_64",a,1.25\n'
                '2026-01-02,"vm 2 cores, x86_64",b,2.25\n')
    expect("columns", run(csv_path, "--columns", "machine,ms", "--where", "method=b"),
           (0, "| machine | ms |\n|---|---|\n| vm 2 cores, x86_64 | 2.5 |\n| vm 2 cores, x86_64 | 2.25 |\n", ""))
    expect("latest", run(csv_path, "--latest", "--columns", "method,ms")[1],
           "| method | ms |\n|---|---|\n| a | 1.25 |\n| b | 2.25 |\n")
    rc, _, err = run(csv_path, "--columns", "nope")
    expect("unknown column", (rc, "no column nope" in err), (1, True))
    expect("unknown option", run(csv_path, "--bogus", "x")[0], 2)

    guide = os.path.join(tmp, "guide.md")
    stale = (f"Text before.\n<!-- results-table {csv_path} --latest --columns method -->\n| old |\n"
             "<!-- end results-table -->\nText after.\n")
    with open(guide, "w") as f:
        f.write(stale)
    expect("check stale", run("--check", guide)[0], 1)
    expect("check leaves the file", open(guide).read(), stale)
    expect("update", run("--update", guide)[0], 0)
    expect("updated guide", open(guide).read(),
           f"Text before.\n<!-- results-table {csv_path} --latest --columns method -->\n| method |\n|---|\n"
           "| a |\n| b |\n<!-- end results-table -->\nText after.\n")
    expect("check current", run("--check", guide)[0], 0)
    with open(guide, "w") as f:
        f.write(f"<!-- results-table {csv_path} -->\nno end\n")
    expect("no end marker", run("--check", guide)[0], 1)

docs = sorted(os.path.join("docs", n) for n in os.listdir(os.path.join(src, "docs")) if n.endswith(".md"))
rc, out, err = run("--check", *docs, cwd=src)
expect("docs/ in step with bench/results (run launch/results-table --update docs/*.md)", (rc, out + err), (0, ""))

for f in failures:
    print("FAIL", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
