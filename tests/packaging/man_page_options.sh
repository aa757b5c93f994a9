#!/usr/bin/env bash
# tests/packaging/man_page_options.sh FRICTIONLAB MAN_PAGE
# The manual page and `frictionlab help` give the same options (each --option and -h, in either
# direction), the page's SYNOPSIS is help's usage form for form, and the page's version is the
# program's. The window's
# keys are the same in help, the manual page and the teachers' guide's table (the manual once
# lacked T, W, L, the arrows and Esc).
set -euo pipefail
frictionlab=$1 page=$2
fail=0
help=$("$frictionlab" help)
# roff writes a hyphen as \-; comment lines (.\") are not the page.
text=$(grep -v '^\.\\"' "$page" | sed 's/\\-/-/g; s/\\f[BIRP]//g')

compare() {  # what, from help, from the page [, what the page is]
  local missing extra other=${4:-the manual page}
  missing=$(comm -23 <(echo "$2") <(echo "$3"))
  extra=$(comm -13 <(echo "$2") <(echo "$3"))
  [[ -z $missing ]] || { echo "FAIL: $1 in frictionlab help but not in $other: $(echo $missing)" >&2; fail=1; }
  [[ -z $extra ]] || { echo "FAIL: $1 in $other but not in frictionlab help: $(echo $extra)" >&2; fail=1; }
  echo "$1: $(echo "$2" | wc -l) in frictionlab help, $(echo "$3" | wc -l) in $other"
}
options() { grep -oE -- '(^|[^a-zA-Z0-9-])--?[a-z][a-z-]*' | grep -oE -- '--?[a-z][a-z-]*' | sort -u; }
compare options "$(echo "$help" | options)" "$(echo "$text" | options)"
# The synopsis: the usage's forms as help writes them, one a line ("frictionlab run LESSON
# [--duration S] ..."), and the page's SYNOPSIS as groff sets it on lines too long to wrap, in
# the same order and word for word. In help a form's words stop at a gap of two spaces, where
# what it does begins, and lines indented to that column (44) hold only what it does.
command -v groff > /dev/null || { echo "FAIL: groff (Debian's groff-base) sets the page's synopsis for this test; install it" >&2; exit 1; }
help_forms=$(echo "$help" | sed '/^Options, with the commands/,$d' | awk '
  { sub(/^usage: /, "       ") }
  match($0, /^ */) && RLENGTH >= 44 { next }
  { line = $0; sub(/^ +/, "", line); sub(/  .*/, "", line) }
  line ~ /^frictionlab( |$)/ { if (form != "") print form; form = line; next }
  { form = form " " line }
  END { if (form != "") print form }')
page_forms=$(groff -man -Tascii -rLL=2000n -P-cbou "$page" 2> /dev/null | sed -n '/^SYNOPSIS/,/^DESCRIPTION/p' |
  sed '1d; $d' | sed -E 's/^ +//; s/ +/ /g; s/ +$//' | grep -v '^$')
[[ $(echo "$help_forms" | wc -l) -ge 14 ]] || { echo "FAIL: found $(echo "$help_forms" | wc -l) forms in frictionlab help's usage" >&2; fail=1; }
if [[ $help_forms != "$page_forms" ]]; then
  echo "FAIL: the manual page's SYNOPSIS is not frictionlab help's usage (< help, > the page):" >&2
  diff <(echo "$help_forms") <(echo "$page_forms") >&2
  fail=1
fi
echo "synopsis: $(echo "$help_forms" | wc -l) forms in frictionlab help, $(echo "$page_forms" | wc -l) in the manual page"

# Keys: help's lines under "Keys in the window:" (the key is what stands before the gap of two
# or more spaces), the page's table rows (KEY, a tab, T{), the rows of the guide's table headed
# "| key | does |".
help_keys=$(echo "$help" | sed -n '/^Keys in the window:/,/^Exit status/p' | grep '^  [^ ]' | sed -E 's/^  //; s/ {2,}.*//' | sort -u)
page_keys=$(grep -v '^\.\\"' "$page" | sed -n '/^\.SH KEYS IN THE WINDOW/,/^\.TE/p' | grep -P '\tT\{$' | cut -f1 | sed 's/^\\&//; s/\\-/-/g; s/\\(<-/←/g; s/\\(->/→/g' | sort -u)
guide=$(dirname "$0")/../../docs/teachers.md
guide_keys=$(awk '/^\| key \| does \|/ {t = 1; next} t && !/^\|/ {exit} t && !/^\|---/' "$guide" | cut -d'|' -f2 | sed -E 's/^ +//; s/ +$//' | sort -u)
[[ -n $help_keys ]] || { echo "FAIL: frictionlab help lists no keys" >&2; fail=1; }
compare keys "$help_keys" "$page_keys"
compare keys "$help_keys" "$guide_keys" "docs/teachers.md's table"

version=$("$frictionlab" --version | cut -d' ' -f2)
grep -q "^\.TH FRICTIONLAB 1 .*\"FrictionLab $version\"" "$page" || { echo "FAIL: the page's .TH is not version $version" >&2; fail=1; }
exit $fail
