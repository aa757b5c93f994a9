#!/bin/bash
# Fails when the lesson API reference stops being a map a student can find things by: the
# index (lessons/reference.md) must link every page of lessons/reference/ and every heading of
# each page, each page must link back to the index, the numbered sections (which the cheat
# sheet, the guide and the code's comments cite) must run 1, 2, 3 ... in the index's order of
# pages, and no file may pass 24 KB. (The reference was one file of 112 KB; a page that grows
# past the limit holds two topics, and is to be split along them.) Anchors are made as
# tests/docs_links.sh makes them; headings inside ``` blocks are not headings.
#   tests/reference_pages.sh SOURCE_DIR
set -u
cd "$1" || exit 2
index=lessons/reference.md
limit=24576
failed=0
fail() { echo "$*" >&2; failed=1; }

prose() { awk '/^```/ { code = !code; next } !code' "$1"; }
# "LEVEL ANCHOR" for each heading of a file.
headings() {
  prose "$1" | awk '/^#+ / {
    level = index($0, " ") - 1; sub(/^#+ /, ""); s = tolower($0); gsub(/[^a-z0-9 _-]/, "", s); gsub(/ /, "-", s)
    print level, s
  }'
}

[[ -f $index ]] || { echo "$index: missing" >&2; exit 1; }
shopt -s nullglob
pages=(lessons/reference/*.md)
(( ${#pages[@]} > 1 )) || fail "lessons/reference/: no pages; the reference is split into pages there, with $index as their index"

for file in "$index" "${pages[@]}"; do
  size=$(wc -c < "$file")
  (( size <= limit )) || fail "$file: $size bytes, over the $limit a page may hold; split it along its topics"
done

for page in "${pages[@]}"; do
  name=${page#lessons/}                      # reference/bodies.md
  grep -qF "]($name)" "$index" || fail "$index: no link to the page $name"
  grep -qF "](../reference.md)" "$page" || fail "$page: no link back to the index, ../reference.md"
  while read -r level anchor; do
    (( level > 1 )) || continue              # the page's title: the page link covers it
    grep -qF "]($name#$anchor)" "$index" || fail "$index: the contents do not list $name#$anchor"
  done < <(headings "$page")
done

# The sections' numbers across the pages, in the order the index links the pages themselves
# (the links with no #heading: its contents).
order=$(grep -oE '\]\(reference/[a-z_]+\.md\)' "$index" | sed -E 's/^\]\(//; s/\)$//' | awk '!seen[$0]++')
# Checked here, outside the $( ) below: a fail inside it would set `failed` in a subshell only.
for name in $order; do
  [[ -f lessons/$name ]] || fail "$index: a link to $name, which is not there"
done
numbers=$(for name in $order; do
  [[ -f lessons/$name ]] || continue
  prose "lessons/$name" | grep -oE '^## [0-9]+\.' | grep -oE '[0-9]+'
done | tr '\n' ' ')
count=$(echo $numbers | wc -w)
expected=$(seq -s ' ' 1 "$count")
[[ $(echo $numbers) == "$expected" ]] ||
  fail "lessons/reference/: the numbered sections run $(echo $numbers) in the index's order of pages, not 1 to $count"
exit $failed
