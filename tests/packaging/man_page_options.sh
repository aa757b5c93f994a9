#!/usr/bin/env bash
# tests/packaging/man_page_options.sh FRICTIONLAB MAN_PAGE
# The manual page and `frictionlab help` give the same commands and the same options (each
# --option and -h, in either direction), and the page's version is the program's.
set -euo pipefail
frictionlab=$1 page=$2
fail=0
help=$("$frictionlab" help)
# roff writes a hyphen as \-; comment lines (.\") are not the page.
text=$(grep -v '^\.\\"' "$page" | sed 's/\\-/-/g; s/\\f[BIRP]//g')

compare() {  # what, from help, from the page
  local missing extra
  missing=$(comm -23 <(echo "$2") <(echo "$3"))
  extra=$(comm -13 <(echo "$2") <(echo "$3"))
  [[ -z $missing ]] || { echo "FAIL: $1 in frictionlab help but not in the manual page: $(echo $missing)" >&2; fail=1; }
  [[ -z $extra ]] || { echo "FAIL: $1 in the manual page but not in frictionlab help: $(echo $extra)" >&2; fail=1; }
  echo "$1: $(echo "$2" | wc -l) in frictionlab help, $(echo "$3" | wc -l) in the manual page"
}
options() { grep -oE -- '(^|[^a-zA-Z0-9-])--?[a-z][a-z-]*' | grep -oE -- '--?[a-z][a-z-]*' | sort -u; }
compare options "$(echo "$help" | options)" "$(echo "$text" | options)"
# Commands: "frictionlab WORD" in help's usage lines and in the page's synopsis (.B lines).
compare commands "$(echo "$help" | grep -oE '^ *(usage: )?frictionlab [a-z]+' | awk '{print $NF}' | sort -u)" \
  "$(echo "$text" | sed -n '/^\.SH SYNOPSIS/,/^\.SH DESCRIPTION/p' | grep -oE '^\.B frictionlab [a-z]+' | awk '{print $NF}' | sort -u)"

version=$("$frictionlab" --version | cut -d' ' -f2)
grep -q "^\.TH FRICTIONLAB 1 .*\"FrictionLab $version\"" "$page" || { echo "FAIL: the page's .TH is not version $version" >&2; fail=1; }
exit $fail
