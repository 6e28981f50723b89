#!/bin/bash
# Runs every `procex ...` line of the ```sh blocks in docs/guide/*.md (in a
# scratch folder beside links to samples/ and docs/), and evaluates every
# recipe the guide names: a guide whose commands fail fails this test.
# usage: run_guide_commands.sh REPO_ROOT FOLDER_OF_PROCEX
set -u
root=$1
export PATH="$2:$PATH"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$root/samples" "$work/samples"
ln -s "$root/docs" "$work/docs"
mkdir -p "$work/out"
cd "$work" || exit 2
failures=0 commands=0
for page in "$root"/docs/guide/*.md; do
  in_sh=0
  while IFS= read -r line; do
    case "$line" in
      '```sh') in_sh=1; continue ;;
      '```'*) in_sh=0; continue ;;
    esac
    [ $in_sh = 1 ] || continue
    cmd=${line%%#*}                    # comments out
    cmd=${cmd#build/app/cli/}          # the guide may name the build's binary
    case "$cmd" in procex\ *) ;; *) continue ;; esac
    commands=$((commands + 1))
    if ! eval "$cmd" > "$work/last.log" 2>&1; then
      echo "FAILED ($(basename "$page")): $cmd"
      sed 's/^/    /' "$work/last.log" | head -20
      failures=$((failures + 1))
    fi
  done < "$page"
done
# Every recipe the guide names evaluates.
for recipe in $(grep -oh 'samples/[a-z0-9_]*\.pxg' "$root"/docs/guide/*.md | sort -u); do
  commands=$((commands + 1))
  # A recipe made for batch runs gets the sample block's first building as its footprint.
  bind=()
  grep -q '"name": "footprint"' "$recipe" && bind=(--footprints samples/footprints/sample_block.geojson --feature 0)
  if ! procex eval "$recipe" "${bind[@]}" -o "out/recipe.glb" > "$work/last.log" 2>&1; then
    echo "FAILED: $recipe does not evaluate"; sed 's/^/    /' "$work/last.log" | head -20
    failures=$((failures + 1))
  fi
done
echo "$commands commands and recipes, $failures failed"
[ "$commands" -gt 0 ] && [ "$failures" = 0 ]
