#!/usr/bin/env python3
"""Checks a doc page's parameter table of one effect against `snell list`.

Usage:
  python3 scripts/check_params_table.py --snell PATH --effect NAME --doc FILE

Every parameter that `snell list` prints for effect NAME must have exactly one row in the table
between <!-- NAME-params:begin --> and <!-- NAME-params:end --> of FILE with the same name, type,
default, range and unit (backticks are ignored; a dash in the range or unit column means none;
`a\\|b` in a cell is a|b), and the table must have no other rows. The first column is the name,
then type, default, range, unit; further columns (the meaning) are not checked.

Exit status: 0 when they match, 1 on a mismatch or when `snell list`, the doc or the table is
missing, 2 on bad arguments. Standard library only.
"""
import argparse
import re
import subprocess
import sys

DASHES = ("-", "\u2013", "\u2014")  # "-", en dash, em dash: no range / no unit
FIELDS = ("type", "default", "range", "unit")


def parse_list(text, effect):
    """The parameters of `effect` in `snell list`'s output, as (name, type, default, range, unit).

    `snell list` prints a line "<effect>: <description>" per effect, then each parameter as
    printf("  %-20s %-6s default %-18s %-26s %-4s %s\\n", name, type, default, range, unit, doc).
    A value longer than its field pushes the rest of the line right, so each field is read up to
    its next space (a range in brackets up to its "]", as "[0.001, 1e+06]" holds a space) and the
    next one starts after the field's padding or after the value, whichever is later.
    """
    params, inside = [], False
    for line in text.splitlines():
        if not line.startswith("  "):
            inside = line.startswith(effect + ":")
            continue
        if not inside:
            continue
        pos = 2

        def token(width, bracketed=False):
            nonlocal pos
            if bracketed and line.startswith("[", pos):
                end = line.index("]", pos) + 1
            else:
                end = pos
                while end < len(line) and line[end] != " ":
                    end += 1
            value = line[pos:end]
            pos = max(end, pos + width) + 1  # the field's padding, then the separating space
            return value.strip()

        name = token(20)
        ptype = token(6)
        if not line.startswith("default ", pos):
            raise ValueError(f"cannot parse `snell list` line: {line!r}")
        pos += len("default ")
        default = token(18)
        prange = token(26, bracketed=True)
        unit = token(4)
        params.append((name, ptype, default, prange, unit))
    return params


def parse_table(path, effect):
    """The rows between the markers: {name: (type, default, range, unit)}; None for a name with
    two rows (reported here). Returns (rows, found_markers, duplicate_messages)."""
    begin, end = f"<!-- {effect}-params:begin -->", f"<!-- {effect}-params:end -->"
    rows, inside, found, messages = {}, False, False, []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if begin in line:
                inside = found = True
                continue
            if end in line:
                inside = False
                continue
            if not inside or not line.startswith("|"):
                continue
            # Cells split at unescaped pipes; `a\|b` in a cell (an enumeration's choices) is a|b.
            cells = [c.strip().replace("\\|", "|")
                     for c in re.split(r"(?<!\\)\|", line.strip()[1:-1])]
            if len(cells) < 6 or set(cells[0]) <= set("-: ") or cells[0].lower() == "name":
                continue
            key = cells[0].strip("`")
            if key in rows:
                messages.append(f"check-table: {path}:{number}: '{key}' has two rows")
                rows[key] = None
                continue
            got = [c.strip("`").strip() for c in cells[1:5]]
            for column in (2, 3):  # a dash in the range or unit column means none
                if got[column] in DASHES:
                    got[column] = ""
            rows[key] = tuple(got)
    return rows, found, messages


def check(list_text, effect, doc):
    """Prints every mismatch; returns the number of errors (0: the table matches)."""
    try:
        params = parse_list(list_text, effect)
    except ValueError as e:
        print(f"check-table: {e}")
        return 1
    if not params:
        print(f"check-table: `snell list` printed no {effect} parameters")
        return 1
    rows, found, messages = parse_table(doc, effect)
    if not found:
        print(f"check-table: no <!-- {effect}-params:begin --> marker in {doc}")
        return 1
    if not rows:
        print(f"check-table: no table rows between <!-- {effect}-params:begin/end --> in {doc}")
        return 1
    for message in messages:
        print(message)
    errors = len(messages)
    for name, *expected in params:
        got = rows.get(name)
        if got is None:
            if name not in rows:  # a duplicate (None) is already reported
                print(f"check-table: {effect} parameter '{name}' is missing from the table")
                errors += 1
            continue
        for field, want, have in zip(FIELDS, expected, got):
            if want != have:
                print(f"check-table: '{name}': {field} is '{have}' in the table, "
                      f"`snell list` says '{want}'")
                errors += 1
    known = {p[0] for p in params}
    for name in rows:
        if name not in known:
            print(f"check-table: the table has '{name}', which `snell list` does not know")
            errors += 1
    if errors:
        print(f"check-table: {errors} mismatch(es) between the {effect} table of {doc} "
              "and `snell list`")
    else:
        print(f"check-table: all {len(params)} {effect} parameters match `snell list` "
              "(name, type, default, range, unit)")
    return errors


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Check a doc page's parameter table of one effect against `snell list`.")
    parser.add_argument("--snell", required=True, help="path of the snell CLI")
    parser.add_argument("--effect", required=True, help="effect name, e.g. water")
    parser.add_argument("--doc", required=True, help="Markdown page holding the table")
    args = parser.parse_args(argv)
    try:
        open(args.doc, encoding="utf-8").close()
    except OSError as e:
        print(f"check-table: cannot read {args.doc}: {e.strerror}")
        return 1
    try:
        result = subprocess.run([args.snell, "list"], capture_output=True, text=True, check=False)
    except OSError as e:
        print(f"check-table: cannot run '{args.snell} list': {e.strerror}")
        return 1
    if result.returncode != 0:
        sys.stdout.write(result.stderr)
        print(f"check-table: '{args.snell} list' failed (exit {result.returncode})")
        return 1
    return 1 if check(result.stdout, args.effect, args.doc) else 0


if __name__ == "__main__":
    sys.exit(main())
