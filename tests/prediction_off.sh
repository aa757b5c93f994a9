#!/bin/sh
# A built-in lesson's row must catch a theory a little wrong (issue 29): a copy of the lesson
# whose named row predicts SHARE more than its theory (1.003: 0.3 % too much) fails `check`, on
# that row, while the same copy with the prediction left as it is passes. A flat 1 % tolerance
# let a theory 0.5 % wrong pass; a tolerance made of the step's and the arithmetic's terms does
# not. The copy is made here, not kept: the lesson's own file is the one tested, as it changes.
#   prediction_off.sh FRICTIONLAB LESSON_FILE ROW SHARE [check options ...]
set -u
frictionlab=$1 lesson=$2 row=$3 share=$4
shift 4
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
copy="$d/$(basename "$lesson")"
# Every expect row passes through a wrapper that scales the named row's numeric prediction by
# FACTOR; words (a row that says why it has no number) are left as they are.
write_copy() {
  cat > "$copy" <<EOF
do
  local expect_as_given = expect
  expect = function(row)
    if row[1] == [[$row]] then
      local given = row.predicted
      row.predicted = function()
        local value = given
        if type(given) == "function" then value = given() end
        if type(value) == "number" then return value * $1 end
        return value
      end
    end
    return expect_as_given(row)
  end
end
EOF
  cat "$lesson" >> "$copy"
}
write_copy 1
"$frictionlab" check "$copy" "$@" > "$d/out" 2>&1 || fail "the copy as it is fails: $(cat "$d/out")"
grep -qF "$row" "$d/out" || fail "no row '$row' in: $(cat "$d/out")"
write_copy "$share"
"$frictionlab" check "$copy" "$@" > "$d/out" 2>&1
status=$?
test $status -eq 1 || fail "the prediction $share times its theory's: exit $status, not 1: $(cat "$d/out")"
# The row named fails (its pass column says NO), and no other row does.
# (The name is matched as text: a row's name may hold brackets.)
awk -v row="$row" 'index($0, row " ") == 1 && / NO$/ { found = 1 } END { exit !found }' "$d/out" ||
  fail "row '$row' did not fail: $(cat "$d/out")"
test "$(grep -cE ' NO$' "$d/out")" -eq 1 || fail "another row failed too: $(cat "$d/out")"
echo ok
