#!/usr/bin/env bash
# figures_test.sh SOURCE_DIR GLINT OUT [FIGURES FLAGS...]: tools/figures --quick writes all
# thirteen figures, a well-formed CSV behind each, and the report page that shows them,
# whose captions' numbers are all in those CSVs (tests/tools/captions_check.py, which
# also edits each caption once and sees the check fail).
set -eu
src=$1
glint=$2
out=$3
shift 3
rm -rf "$out"
"$src/tools/figures" --quick --glint "$glint" --out "$out" "$@"
/usr/bin/python3 - "$out" <<'PY'
import csv, glob, os, sys
out = sys.argv[1]
pngs = sorted(glob.glob(os.path.join(out, "[0-9]*-*.png")))
csvs = sorted(glob.glob(os.path.join(out, "[0-9]*-*.csv")))
assert len(pngs) == 13, f"{len(pngs)} figures: {pngs}"
figures = {os.path.basename(c).split("-")[0] for c in csvs}
assert len(figures) == 13, f"tables of {len(figures)} figures: {csvs}"
for p in pngs:
    with open(p, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", p
    assert os.path.getsize(p) > 5000, f"{p} is suspiciously small"
for c in csvs:
    rows = list(csv.reader(open(c)))
    assert len(rows) >= 2, f"{c}: no data"
    assert all(len(r) == len(rows[0]) for r in rows), f"{c}: ragged rows"
    for r in rows[1:]:
        for v in r:
            assert v.lower() not in ("nan", "inf", "-inf"), f"{c}: {v}"
readme = open(os.path.join(out, "README.md")).read()
for p in pngs:
    assert os.path.basename(p) in readme, f"README.md does not show {p}"
import re
assert not re.search(r"\b(nan|inf)\b", readme.lower()), "a NaN or Inf reached the report"
print(f"figures: {len(pngs)} figures, {len(csvs)} tables, README.md ok")
PY
/usr/bin/python3 "$src/tests/tools/captions_check.py" "$out"
