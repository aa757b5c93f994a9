#!/bin/sh
# frictionlab run --csv: what the file holds, where it may be written, and what an interrupted
# run leaves. Everything happens in a temporary folder of its own; nothing else is touched (the
# non-regular targets are a FIFO and a symbolic link made there, never a device).
#   csv_output.sh FRICTIONLAB
set -u
frictionlab=$1
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# A run's file: a byte-order mark (a spreadsheet then reads ° and μ right), a line saying which
# run it is, the columns with their units, one row a step.
"$frictionlab" run incline --duration 0.5 --hz 120 --set angle=25 --csv "$d/run.csv" >/dev/null || fail "run --csv exited $?"
head -c 3 "$d/run.csv" | od -An -tx1 | grep -q 'ef bb bf' || fail "no byte-order mark"
sed -n 1p "$d/run.csv" | grep -q '# FrictionLab run of .*incline.lua at 120 Hz; 1 sub-step(s); stick-slip; angle = 25 °;' \
  || fail "the first line does not say which run: $(sed -n 1p "$d/run.csv")"
sed -n 2p "$d/run.csv" | grep -q '^t (s),block.x (m),block.y (m),block.angle (rad),block.vx (m/s),block.vy (m/s),block.omega (rad/s),distance (m),speed (m/s),' \
  || fail "the columns: $(sed -n 2p "$d/run.csv")"
sed -n 2p "$d/run.csv" | grep -q 'ground\|slope\.' && fail "a fixed body has columns"
test "$(wc -l < "$d/run.csv")" -eq 62 || fail "expected 2 heading lines and 60 rows, got $(wc -l < "$d/run.csv") lines"
test "$(ls -A "$d")" = run.csv || fail "something besides run.csv was left: $(ls -A "$d")"

# Run again over it: a file FrictionLab wrote is replaced.
"$frictionlab" run incline --duration 0.25 --hz 120 --csv "$d/run.csv" >/dev/null || fail "a second run over its own CSV exited $?"
test "$(wc -l < "$d/run.csv")" -eq 32 || fail "the second run did not replace the first"

# Anything else is refused with exit 2, and left as it was.
echo "my own notes" > "$d/notes.csv"
mkfifo "$d/pipe.csv"
ln -s notes.csv "$d/link.csv"
for target in notes.csv pipe.csv link.csv; do
  "$frictionlab" run incline --duration 0.1 --csv "$d/$target" >/dev/null 2>"$d/err"
  status=$?
  test $status -eq 2 || fail "--csv $target exited $status"
  grep -q -- "--csv $d/$target: " "$d/err" || fail "--csv $target: the message does not name it: $(cat "$d/err")"
done
test "$(cat "$d/notes.csv")" = "my own notes" || fail "notes.csv was changed"
test -p "$d/pipe.csv" || fail "the FIFO was replaced"
test -L "$d/link.csv" || fail "the symbolic link was replaced"
rm -f "$d/err"
test "$(ls -A "$d" | sort | tr '\n' ' ')" = "link.csv notes.csv pipe.csv run.csv " || fail "left behind: $(ls -A "$d")"

# --csv -: the rows on standard output, the table on standard error.
"$frictionlab" run incline --duration 0.1 --hz 120 --csv - >"$d/out" 2>"$d/table" || fail "--csv - exited $?"
sed -n 2p "$d/out" | grep -q '^t (s),' || fail "--csv - wrote no CSV to standard output"
test "$(wc -l < "$d/out")" -eq 14 || fail "--csv -: expected 14 lines, got $(wc -l < "$d/out")"
grep -q 'expectations met' "$d/table" || fail "--csv -: the table is not on standard error"
rm -f "$d/out" "$d/table"

# Ctrl-C in the middle of a long run: no CSV and no temporary file left, and the signal's status.
"$frictionlab" run spring_pull --duration 3000 --hz 2000 --csv "$d/long.csv" >/dev/null 2>&1 &
pid=$!
sleep 1
kill -INT $pid
wait $pid
status=$?
test $status -eq 130 || fail "interrupted, it exited $status, not 130"
test -e "$d/long.csv" && fail "an interrupted run left long.csv"
ls -A "$d" | grep -q partial && fail "an interrupted run left a temporary file: $(ls -A "$d")"
echo "ok"
