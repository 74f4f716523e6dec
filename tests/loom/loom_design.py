"""The design the loom's tests and figures weave, without numpy: three regions across the
columns (plain, twill 2/2, 5-end satin), 1 where the warp (column c) lies over the weft (row r).
Row r reads weft -r of each pattern (rows run down, wefts up)."""


def three_regions(size):
    rows = []
    for r in range(size):
        row = []
        for c in range(size):
            region = 3 * c // size
            if region == 0:
                over = (c + r) % 2 == 0
            elif region == 1:
                over = (c + r) % 4 < 2
            else:
                over = (c + 2 * r) % 5 < 4
            row.append(1 if over else 0)
        rows.append(row)
    return rows


def write_pbm(path, rows):
    with open(path, "w") as f:
        f.write("P1\n%d %d\n" % (len(rows[0]), len(rows)))
        f.write("\n".join("".join(map(str, row)) for row in rows) + "\n")
