# tests/lib/cli.sh: the command-line tests' checks (tests/cli.sh, tests/cli-files.sh),
# sourced after tests/lib/check.sh.
lines() { awk 'END { print NR }' "$1"; } # counts a last line without a newline too
first_line() { sed -n 1p "$1" 2>/dev/null; }
data_rows() { awk 'NR > 1' "$1" 2>/dev/null | awk 'END { print NR }'; }

# shows a file's first lines in one line, for failure messages
show() { head -c 300 "$1" | tr '\n' '|'; }

# expect_ok ARGS...: runs and checks it exited 0 with nothing on stderr. Returns 1 (after
# reporting) otherwise, so a caller can skip the checks that would only repeat it.
expect_ok() {
    run "$@"
    if [ "$rc" -ne 0 ] || [ -s "$err" ]; then
        fail "$cmd: expected exit 0 and empty stderr, got exit $rc, stderr: $(show "$err")"
        return 1
    fi
    return 0
}

# expect_usage_error NEEDLE... -- ARGS...: a bad option or value. Exit 2,
# exactly one line on stderr starting "springsim: " and naming the option and value
# (each NEEDLE must appear in it), nothing on stdout.
expect_usage_error() {
    needles=
    while [ "$1" != -- ]; do
        needles="$needles$1
"
        shift
    done
    shift
    expect_one_line_error 2 "$needles" "$@"
}

# expect_one_line_error STATUS NEEDLES ARGS...: NEEDLES is newline-separated.
expect_one_line_error() {
    want=$1
    needles=$2
    shift 2
    run "$@"
    bad=
    [ "$rc" -eq "$want" ] || bad="$bad exit $rc (expected $want);"
    [ -s "$out" ] && bad="$bad stdout not empty: $(show "$out");"
    n=$(lines "$err")
    [ "$n" -eq 1 ] || bad="$bad $n lines on stderr (expected 1);"
    line=$(first_line "$err")
    case $line in springsim:\ *) ;; *) bad="$bad stderr does not start 'springsim: ';" ;; esac
    old_ifs=$IFS
    IFS='
'
    set -f # a needle like [bogus] is not a glob
    for needle in $needles; do
        case $line in *"$needle"*) ;; *) bad="$bad stderr does not name \"$needle\";" ;; esac
    done
    IFS=$old_ifs
    set +f
    if [ -n "$bad" ]; then
        fail "$cmd:$bad stderr: $(show "$err")"
    else
        pass
    fi
}

# expect_equal WHAT EXPECTED ACTUAL
expect_equal() {
    if [ "$2" = "$3" ]; then pass; else fail "$1: expected '$2', got '$3'"; fi
}

# expect_rows N ARGS...: the command succeeds and prints N data rows after its header.
expect_rows() {
    want=$1
    shift
    expect_ok "$@" || return
    expect_equal "$cmd: data rows" "$want" "$(data_rows "$out")"
}

# expect_same_output WHAT FILE1 FILE2
expect_same_output() {
    if cmp -s "$2" "$3"; then pass; else fail "$1: outputs differ"; fi
}

# check_csv FILE WHAT: every row has as many fields as the header, and every field of
# every data row is a plain finite number (no nan, no inf, nothing empty).
check_csv() {
    bad=$(awk -F, '
        NR == 1 { nf = NF; next }
        NF != nf { print "row " NR - 1 " has " NF " fields, header has " nf; exit }
        { for (i = 1; i <= NF; i++)
              if ($i !~ /^-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?$/) {
                  print "row " NR - 1 " field " i " is \"" $i "\""; exit } }' "$1")
    if [ -z "$bad" ]; then pass; else fail "$2: $bad"; fi
}

# expect_no_tmp DIR WHAT: no temporary output files (FILE.tmp-XXXXXX) left behind.
expect_no_tmp() {
    left=
    for g in "$1"/*.tmp* "$1"/.*.tmp*; do
        [ -e "$g" ] && left="$left $(basename "$g")"
    done
    if [ -z "$left" ]; then pass; else fail "$2: temporary files left in $1: $left"; fi
}

# column FILE NAME ROW: the field of data row ROW (1 = first) under header NAME.
column() {
    awk -F, -v name="$2" -v row="$3" '
        NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next }
        NR - 1 == row { print $c; exit }' "$1" 2>/dev/null
}
