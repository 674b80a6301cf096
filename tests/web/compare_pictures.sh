# Sourced by the page's comparison scripts, whose arguments are BASE_URL LUZ SCRATCH_DIR and
# which set $here (their folder) first: holds a page's picture to `luz render`'s with `luz
# compare` (the mean relative error over lit pixels). A failed check sets status=1 and the
# script goes on, so one run reports every comparison.
base=$1 luz=$2 scratch=$3
scenes="$(dirname "$here")/../scenes"
mkdir -p "$scratch"
status=0

# The mean relative error over lit pixels of A against B, in percent.
error_of() { "$luz" compare "$1" "$2" | sed -n 's/^mean relative error over lit pixels: .*(\([0-9.]*\)%.*/\1/p'; }

# within A B LIMIT WHAT: A and B agree within LIMIT percent; apart A B LIMIT WHAT: they do not.
within() {
  percent=$(error_of "$1" "$2")
  verdict=$(awk -v p="$percent" -v l="$3" 'BEGIN { print (p != "" && p + 0 <= l + 0) ? "ok" : "FAILED" }')
  echo "$4: mean relative error over lit pixels $percent% (limit $3%): $verdict"
  [ "$verdict" = ok ] || status=1
}
apart() {
  percent=$(error_of "$1" "$2")
  verdict=$(awk -v p="$percent" -v l="$3" 'BEGIN { print (p != "" && p + 0 > l + 0) ? "ok" : "FAILED" }')
  echo "$4: mean relative error over lit pixels $percent% (must exceed $3%): $verdict"
  [ "$verdict" = ok ] || status=1
}
