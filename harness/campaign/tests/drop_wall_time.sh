# Prints a results table without its wall_time column (the one cell that differs between runs of the
# same campaign), for comparing tables. Cells here never hold quoted commas before wall_time.
drop_wall_time() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_time") w = i }
             { out = ""; for (i = 1; i <= NF; ++i) if (i != w) out = out (out == "" && i == 1 ? "" : ",") $i; print out }' "$1"
}
