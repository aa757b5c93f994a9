#!/bin/bash
# Fails when a relative link in the docs names a file that is not there, or an anchor
# (#heading) that no heading of its file makes. Anchors are made as GitHub makes them:
# lower case, every character but letters, digits, spaces, '-' and '_' dropped, spaces made
# '-' (the docs' headings are ASCII). Links inside ``` blocks are not links.
#   tests/docs_links.sh SOURCE_DIR
set -u
cd "$1" || exit 2
# Every doc by folder, so that a new page is checked without being listed here: the README,
# docs/, the students' guide with its reference and the reference's pages, and each code
# folder's README (a build folder in the tree, which has a CMakeCache.txt, is not a doc).
shopt -s nullglob
docs=(README.md docs/*.md lessons/*.md lessons/reference/*.md)
for readme in */README.md; do
  [[ -e $(dirname "$readme")/CMakeCache.txt ]] || docs+=("$readme")
done
failed=0

# The text of a file outside its ``` blocks.
prose() { awk '/^```/ { code = !code; next } !code' "$1"; }

# Every anchor a file's headings make, one a line (a repeated heading's -1, -2 ... too).
anchors() {
  prose "$1" | awk '/^#+ / {
    sub(/^#+ /, ""); s = tolower($0); gsub(/[^a-z0-9 _-]/, "", s); gsub(/ /, "-", s)
    if (s in seen) { print s "-" seen[s]; seen[s]++ } else { print s; seen[s] = 1 }
  }'
}

for doc in "${docs[@]}"; do
  test -f "$doc" || { echo "$doc: missing" >&2; failed=1; continue; }
  dir=$(dirname "$doc")
  while IFS= read -r target; do
    case "$target" in http://* | https://* | mailto:*) continue ;; esac
    path=${target%%#*}
    anchor=
    [[ $target == *"#"* ]] && anchor=${target#*#}
    if [[ -z $path ]]; then file=$doc; else file=$dir/$path; fi
    if [[ ! -e $file ]]; then
      echo "$doc: a link to $target, which is not there" >&2
      failed=1
    elif [[ -n $anchor && $file == *.md ]] && ! anchors "$file" | grep -qxF -- "$anchor"; then
      echo "$doc: a link to $target, but no heading of $file makes #$anchor" >&2
      failed=1
    fi
  done < <(prose "$doc" | grep -o '\]([^)[:space:]]*)' | sed 's/^](//; s/)$//')
done
exit $failed
