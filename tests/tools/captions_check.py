#!/usr/bin/python3
"""captions_check.py REPORT_DIR: every number in every caption of REPORT_DIR/README.md
(tools/figures) is a number of the tables linked below that caption, at the precision
the caption prints it (a percentage as its fraction). Then the check is turned on
itself: one number of each caption is edited and the edited page must fail."""
import csv
import math
import os
import re
import sys

NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?(?:e[-+]?\d+)?%?")


def sections(readme):
    """[(title, caption, [csv names])] of the page."""
    out = []
    for block in re.split(r"\n## ", readme)[1:]:
        paragraphs = [p.strip() for p in block.split("\n\n")]
        title = paragraphs[0]
        tables = [p for p in paragraphs if p.startswith("Numbers:")]
        if not tables or not paragraphs[1].startswith("!["):
            continue  # "Skipped"
        out.append((title, paragraphs[2], re.findall(r"\]\(([^)]+\.csv)\)", tables[0])))
    return out


def cells(folder, names):
    values = []
    for name in names:
        for row in csv.reader(open(os.path.join(folder, name))):
            for v in row:
                try:
                    values.append(float(v))
                except ValueError:
                    pass
    return values


def tolerance(token):
    text = token.rstrip("%")
    mantissa, _, exponent = text.partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    tol = 0.5 * 10.0 ** (int(exponent or 0) - decimals)
    value = float(text)
    if token.endswith("%"):
        value, tol = value / 100, tol / 100
    return value, tol


def problems(folder, readme):
    found = []
    for title, caption, tables in sections(readme):
        values = cells(folder, tables)
        for token in NUMBER.findall(caption):
            value, tol = tolerance(token)
            if not any(abs(v - value) <= tol * (1 + 1e-9) + 1e-12 for v in values):
                found.append(f"{title}: {token} is in no cell of {', '.join(tables)}")
    return found


def edited(token, factor):
    value, _ = tolerance(token)
    text = token.rstrip("%")
    decimals = len(text.split("e")[0].split(".")[1]) if "." in text.split("e")[0] else 0
    new = value * factor + factor  # distinct for every factor, also when value is 0
    if token.endswith("%"):
        return f"{100 * new:.{decimals}f}%"
    if "e" in text:
        return f"{new:.{decimals}e}"
    return f"{new:.{decimals}f}"


def main(folder):
    readme = open(os.path.join(folder, "README.md")).read()
    bad = problems(folder, readme)
    for b in bad:
        print("FAIL:", b)
    checked = 0
    for title, caption, tables in sections(readme):
        tokens = NUMBER.findall(caption)
        if not tokens:
            continue
        values = cells(folder, tables)
        for factor in (1.5, 2.7, 7.3, 13.1):
            new = edited(tokens[0], factor)
            v, tol = tolerance(new)
            if not any(abs(x - v) <= tol for x in values):
                break
        changed = readme.replace(caption, caption.replace(tokens[0], new, 1))
        if not problems(folder, changed):
            print(f"FAIL: {title}: editing {tokens[0]} to {new} went unnoticed")
            bad.append(title)
        checked += 1
    print(f"captions: {len(sections(readme))} captions, every number in its tables; "
          f"{checked} edited captions caught")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
