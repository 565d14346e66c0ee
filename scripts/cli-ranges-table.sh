#!/bin/sh
# Prints the option range table of docs/cli.md ("Option ranges") from the
# built CLI's --help, i.e. from each command's OptionSpec (app/cli/args.h):
#   scripts/cli-ranges-table.sh build/app/mozzi-cli
# The robustness test (app_cli_robustness_cli) fails when the page and the
# code disagree.
set -eu
cli=${1:-build/app/mozzi-cli}
echo "| command | option | what | valid range |"
echo "| --- | --- | --- | --- |"
for cmd in $("$cli" --help | awk '/^Commands:/ {on = 1; next} on && /^  [a-z]/ && !/mozzi-cli/ {print $1}'); do
  "$cli" "$cmd" --help | awk -v cmd="$cmd" '
    /^Numeric options/ {on = 1; next}
    on && /^  --/ {
      line = substr($0, 3)
      split(line, parts, " ")
      name = parts[1]
      rest = substr(line, length(name) + 1)
      sub(/^ [^ ]*[^ ] +/, "", rest)   # the value form (k,c,hW), if any
      sub(/^ +/, "", rest)
      i = index(rest, ": ")
      printf "| `%s` | `%s` | %s | %s |\n", cmd, name, substr(rest, 1, i - 1), substr(rest, i + 2)
      next
    }
    on && !/^  --/ {on = 0}'
done
