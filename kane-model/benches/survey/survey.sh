#!/usr/bin/env bash
# Public research Autolev files, run as written: `kane check`, `kane gen`, a 1 s `gyro-sim run`
# and `kane code` (the file's CODE statements, each C or Fortran program written compiled by cc or
# gfortran) of each file listed in manifest.tsv (repository, commit, path, blob), with the first
# error of each that fails. Not part of the build or the tests; needs git and the network to fetch.
#
# usage: kane-model/benches/survey/survey.sh [CACHE] [KIND]
#   CACHE  where repositories are fetched (default: ~/.cache/kane-survey)
#   KIND   research (default), course, grammar or all
#   KANE and GYRO_SIM in the environment: the binaries to survey (default: built here, release)
#   SURVEY_SOURCE in the environment: where OWNER/NAME repositories are fetched from (default:
#   https://github.com; a folder of local clones laid out OWNER/NAME works too)
# Writes CACHE/results.tsv (path, check, gen, run, code, first error) and prints the counts;
# CACHE/code.tsv has one line per CODE statement (path, statement, written, compiled, error).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
cache="${1:-$HOME/.cache/kane-survey}"
kind="${2:-research}"
mkdir -p "$cache/repos" "$cache/out"
if [ -z "${KANE:-}" ] || [ -z "${GYRO_SIM:-}" ]; then
  (cd "$root" && cargo build --release -q --bin kane --bin gyro-sim)
fi
kane="$(realpath "${KANE:-$root/target/release/kane}")"
gyro="$(realpath "${GYRO_SIM:-$root/target/release/gyro-sim}")"

# A repository at a commit, fetched once.
checkout() {
  local repo=$1 commit=$2 dir="$cache/repos/${1//\//+}@${2:0:10}"
  if [ ! -d "$dir/.git" ]; then
    git init -q "$dir"
    git -C "$dir" fetch -q --depth 1 "${SURVEY_SOURCE:-https://github.com}/$repo" "$commit"
    git -C "$dir" checkout -q FETCH_HEAD
  fi
  echo "$dir"
}

# One line per CODE statement of file $2 (shown as $1) into code.tsv: whether its program was
# written into $3.code, and, for a C or Fortran program, whether cc or gfortran compiles it.
survey_code_statements() {
  local shown=$1 file=$2 log=$3 line name written compiled reason
  grep -iE '^[[:space:]]*CODE[[:space:]]' "$file" | tr -d '\r' | while read -r line; do
    name=$(printf '%s' "$line" | sed -E 's/^[^)]*\)[[:space:]]*//; s/[,[:space:]%].*//')
    name=$(printf '%s' "$name" | tr '\\' /)
    name="${name%.*}.$(printf '%s' "${name##*.}" | tr '[:upper:]' '[:lower:]')"
    written=no; compiled=-; reason=""
    if [ -f "$log.code/$name" ]; then
      written=yes
      case "$name" in
        *.c) compiled=no; cc -std=c99 -O0 -o "$log.code/${name%.c}" "$log.code/$name" -lm 2>/dev/null && compiled=yes ;;
        *.f|*.for|*.f90) compiled=no; gfortran -O0 -o "$log.code/${name%.*}" "$log.code/$name" 2>/dev/null && compiled=yes ;;
      esac
    else
      reason=$(grep -v -E '^(wrote |[0-9]+ of [0-9]+ CODE)' "$log.codelog" 2>/dev/null | grep -m1 -E '[a-z]' | cut -c1-160 || true)
    fi
    printf '%s\t%s\t%s\t%s\t%s\n' "$shown" "$line" "$written" "$compiled" "$reason" >> "$statements"
  done
}

results="$cache/results.tsv"
printf 'file\tcheck\tgen\trun\tcode\terror\n' > "$results"
statements="$cache/code.tsv"
printf 'file\tstatement\twritten\tcompiled\terror\n' > "$statements"
tail -n +2 "$here/manifest.tsv" | while IFS=$'\t' read -r repo commit path blob what _models; do
  [ "$kind" = all ] || [ "$what" = "$kind" ] || continue
  dir=$(checkout "$repo" "$commit")
  file="$dir/$path"
  if [[ "$path" == *'!'* ]]; then
    # A file inside a committed tar archive: unpacked beside it.
    archive="$dir/${path%%!*}"; member="${path#*!}"
    [ -f "$archive.d/$member" ] || { mkdir -p "$archive.d" && tar -xf "$archive" -C "$archive.d" "$member"; }
    file="$archive.d/$member"
  fi
  got=$(git hash-object "$file" 2>/dev/null || echo missing)
  if [ "$got" != "$blob" ]; then
    printf '%s:%s\t-\t-\t-\t-\tnot surveyed: blob %s, the manifest has %s\n' "$repo" "$path" "$got" "$blob" >> "$results"
    continue
  fi
  key=$(printf '%s' "$repo/$path" | md5sum | cut -c1-10)
  log="$cache/out/$key"
  check=0; gen=-; run=-
  (cd "$(dirname "$file")" && timeout 120 "$kane" check "$file") > "$log.check" 2>&1 || check=$?
  if [ "$check" = 0 ]; then
    gen=0; timeout 300 "$kane" gen "$file" > "$log.rs" 2> "$log.gen" || gen=$?
    if [ "$gen" = 0 ]; then
      run=0
      timeout 300 "$gyro" run --model "$file" --t-final 1 --engine instant --no-view --out "$log.run" \
        > "$log.runlog" 2>&1 || run=$?
    fi
  fi
  code=-
  if [ "$check" = 0 ] && grep -qiE '^[[:space:]]*CODE[[:space:]]' "$file"; then
    code=0; rm -rf "$log.code"; mkdir -p "$log.code"
    # A program named in a folder is written there: the folders the repository has, beside the
    # file or beside a folder above it (where its author ran Autolev), are made here.
    grep -iE '^[[:space:]]*CODE[[:space:]]' "$file" | tr -d '\r' | tr '\\' / |
      sed -E 's/^[^)]*\)[[:space:]]*//; s/[,[:space:]].*//' | while read -r name; do
        sub=$(dirname "$name") above=$(dirname "$file")
        while [ "$sub" != . ] && [ "${above#"$dir"}" != "$above" ]; do
          if [ -d "$above/$sub" ]; then mkdir -p "$log.code/$sub"; break; fi
          above=$(dirname "$above")
        done
      done
    timeout 300 "$kane" code "$file" --out "$log.code" > "$log.codelog" 2>&1 || code=$?
    survey_code_statements "$repo:$path" "$file" "$log"
  fi
  error=$(cat "$log.check" "$log.gen" "$log.runlog" "$log.codelog" 2>/dev/null | grep -m1 -E '×|error' | sed "s|$dir/||" | cut -c1-200 || true)
  printf '%s:%s\t%s\t%s\t%s\t%s\t%s\n' "$repo" "$path" "$check" "$gen" "$run" "$code" "$error" >> "$results"
done
awk -F'\t' 'NR > 1 && $2 != "-" {n++; if ($2 == 0) c++; if ($3 == 0) g++; if ($4 == 0) r++}
  END {printf "%d files: check %d (%.0f %%), gen %d (%.0f %%), 1 s run %d (%.0f %%)\n", n, c, 100*c/n, g, 100*g/n, r, 100*r/n}' "$results"
awk -F'\t' 'NR > 1 {n++; if ($3 == "yes") w++; if ($4 == "yes") c++; if ($4 != "-") cc++}
  END {printf "%d CODE statements: %d programs written (%.0f %%), %d of %d C and Fortran programs compiled\n", n, w, 100*w/(n ? n : 1), c, cc}' "$statements"
echo "results: $results"
echo "CODE statements: $statements"
