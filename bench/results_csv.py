"""Writes a benchmark's rows to bench/results/<stem>_<date>.csv (the figures docs/benchmarks.md quotes)."""
import csv, datetime, os


def write_results(stem, rows):
    os.makedirs("bench/results", exist_ok=True)
    out = "bench/results/%s_%s.csv" % (stem, datetime.date.today().isoformat())
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("wrote", out)
    return out
