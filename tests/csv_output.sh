#!/bin/sh
# frictionlab run --csv: what the file holds, where it may be written, and what an interrupted
# run leaves. Everything happens in a temporary folder of its own; nothing else is touched (the
# non-regular targets are a FIFO and a symbolic link made there, never a device).
#   csv_output.sh FRICTIONLAB               the file, its settings file, and where they may go
#   csv_output.sh FRICTIONLAB spreadsheet   the file as LibreOffice Calc reads it
set -u
frictionlab=$1
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
bom=$(printf '\357\273\277')

if [ "${2:-}" = spreadsheet ]; then
  # LibreOffice Calc, headless, reads the CSV as a student's spreadsheet would (the text import's
  # settings: UTF-8, commas, English numbers) and writes it as a flat OpenDocument spreadsheet,
  # whose XML says what each cell holds. The first row must be the header (no comment line
  # before it, and no byte-order mark left in its first cell), with the units as written, and
  # the second row's first cell the number 1/120.
  command -v soffice >/dev/null || fail "soffice is missing: FRICTIONLAB_TESTS=1 scripts/setup.sh installs libreoffice-calc-nogui"
  "$frictionlab" run tipping_box --duration 0.05 --hz 120 --csv "$d/tip.csv" >/dev/null || fail "run --csv exited $?"
  HOME="$d/home" soffice --headless --infilter='CSV:44,34,76,1,,1033' --convert-to fods --outdir "$d/out" "$d/tip.csv" \
    >"$d/soffice.log" 2>&1 || fail "soffice exited $?: $(cat "$d/soffice.log")"
  test -s "$d/out/tip.fods" || fail "soffice wrote no spreadsheet: $(cat "$d/soffice.log")"
  # One line per row, cells as "type|value|text".
  tr -d '\n' < "$d/out/tip.fods" | sed 's|</table:table-row>|\n|g' > "$d/rows"
  first_cell() { sed -n "$1p" "$d/rows" | sed 's|<table:table-cell|\n&|g' | sed -n 2p; }
  cell_text() { sed -n "$1p" "$d/rows" | sed 's|<table:table-cell|\n&|g' | sed -n "$(($2 + 1))p" | sed 's|.*<text:p>\(.*\)</text:p>.*|\1|'; }
  test "$(cell_text 1 1)" = "t (s)" || fail "the first cell is not t (s): $(first_cell 1)"
  sed -n 1p "$d/rows" | grep -q '<text:p>tilt (°)</text:p>' || fail "no tilt (°) in the first row: $(sed -n 1p "$d/rows" | head -c 600)"
  sed -n 1p "$d/rows" | grep -q '<text:p>push (N)</text:p>' || fail "no push (N) in the first row"
  first_cell 2 | grep -q 'office:value-type="float" office:value="0.008333333' \
    || fail "the first time is not read as the number 0.008333333: $(first_cell 2)"
  echo "ok"
  exit 0
fi

# A run's file: a byte-order mark (a spreadsheet then reads ° and μ right), then at once the
# columns with their units, one row a step. Which run it is goes beside it, in run_settings.txt.
"$frictionlab" run incline --duration 0.5 --hz 120 --set angle=25 --csv "$d/run.csv" >/dev/null || fail "run --csv exited $?"
head -c 3 "$d/run.csv" | od -An -tx1 | grep -q 'ef bb bf' || fail "no byte-order mark"
test "$(sed -n 1p "$d/run.csv")" = "${bom}t (s),distance (m),speed (m/s),friction_force (N),normal_force (N),any_contact_slipping,hand_pulled,gauge (N)" \
  || fail "the first line is not the columns: $(sed -n 1p "$d/run.csv")"
grep -q '#' "$d/run.csv" && fail "a comment line: $(grep '#' "$d/run.csv")"
sed -n 2p "$d/run.csv" | grep -q '^0.00833333333,' || fail "the first row is not at 1/120 s: $(sed -n 2p "$d/run.csv")"
test "$(wc -l < "$d/run.csv")" -eq 61 || fail "expected the header and 60 rows, got $(wc -l < "$d/run.csv") lines"
sed -n 1p "$d/run_settings.txt" | grep -q '^FrictionLab run of .*incline.lua$' || fail "the settings do not say which lesson: $(cat "$d/run_settings.txt")"
grep -qx '120 Hz, 1 sub-step(s), stick-slip friction' "$d/run_settings.txt" || fail "the settings lack the step: $(cat "$d/run_settings.txt")"
grep -qx 'angle = 25 °' "$d/run_settings.txt" || fail "the settings lack the angle: $(cat "$d/run_settings.txt")"
test "$(ls -A "$d" | tr '\n' ' ')" = "run.csv run_settings.txt " || fail "something besides run.csv and its settings was left: $(ls -A "$d")"

# Run again over it: files FrictionLab wrote are replaced.
"$frictionlab" run incline --duration 0.25 --hz 120 --csv "$d/run.csv" >/dev/null || fail "a second run over its own CSV exited $?"
test "$(wc -l < "$d/run.csv")" -eq 31 || fail "the second run did not replace the first"
grep -qx 'angle = 35 °' "$d/run_settings.txt" || fail "the second run did not replace the settings: $(cat "$d/run_settings.txt")"

# An earlier FrictionLab's file (its comment line first) is replaced too, so a teacher's script
# that writes the same file every class works after an upgrade; the same header with a column a
# student added at its end is the student's, and refused.
printf '%s# FrictionLab run of incline.lua at 240 Hz\nt (s),x (m)\n0,0\n' "$bom" > "$d/earlier.csv"
"$frictionlab" run incline --duration 0.1 --csv "$d/earlier.csv" >/dev/null 2>"$d/err" || fail "an earlier FrictionLab's CSV was refused: $(cat "$d/err")"
sed -n 1p "$d/earlier.csv" | grep -q "^${bom}t (s),distance (m)," || fail "an earlier FrictionLab's CSV was not replaced"
rm -f "$d/earlier.csv" "$d/earlier_settings.txt" "$d/err"
noted="${bom}t (s),distance (m),speed (m/s),friction_force (N),normal_force (N),any_contact_slipping,hand_pulled,gauge (N),my notes"
printf '%s\n0,0,0,0,0,0,0,,the block has not moved yet\n' "$noted" > "$d/noted.csv"
"$frictionlab" run incline --duration 0.1 --csv "$d/noted.csv" >/dev/null 2>"$d/err"
test $? -eq 2 || fail "--csv over a student's CSV with a column of their own did not exit 2"
test "$(sed -n 1p "$d/noted.csv")" = "$noted" || fail "the student's CSV was changed"
rm -f "$d/noted.csv" "$d/err"

# A settings file FrictionLab did not write is refused with exit 2 before the run, and no CSV is written.
echo "my own settings" > "$d/mine_settings.txt"
"$frictionlab" run incline --duration 0.1 --csv "$d/mine.csv" >/dev/null 2>"$d/err"
test $? -eq 2 || fail "--csv mine.csv over someone's mine_settings.txt did not exit 2"
grep -q -- "--csv $d/mine_settings.txt: " "$d/err" || fail "the message does not name mine_settings.txt: $(cat "$d/err")"
test -e "$d/mine.csv" && fail "mine.csv was written"
test "$(cat "$d/mine_settings.txt")" = "my own settings" || fail "mine_settings.txt was changed"
rm -f "$d/mine_settings.txt" "$d/err"

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
test "$(ls -A "$d" | sort | tr '\n' ' ')" = "link.csv notes.csv pipe.csv run.csv run_settings.txt " || fail "left behind: $(ls -A "$d")"

# --csv -: the rows on standard output, the settings and the table on standard error.
"$frictionlab" run incline --duration 0.1 --hz 120 --csv - >"$d/out" 2>"$d/table" || fail "--csv - exited $?"
sed -n 1p "$d/out" | grep -q "^${bom}t (s)," || fail "--csv - wrote no CSV to standard output"
test "$(wc -l < "$d/out")" -eq 13 || fail "--csv -: expected 13 lines, got $(wc -l < "$d/out")"
grep -q 'expectations met' "$d/table" || fail "--csv -: the table is not on standard error"
grep -q '^FrictionLab run of .*incline.lua$' "$d/table" || fail "--csv -: the settings are not on standard error"
grep -qx '120 Hz, 1 sub-step(s), stick-slip friction' "$d/table" || fail "--csv -: the settings lack the step"
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
test -e "$d/long_settings.txt" && fail "an interrupted run left long_settings.txt"
ls -A "$d" | grep -q partial && fail "an interrupted run left a temporary file: $(ls -A "$d")"
echo "ok"
