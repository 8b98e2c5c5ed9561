#!/usr/bin/env bash
# shadetree render under a real mpirun (Open MPI): two ranks write exactly
# the bytes one process writes, for a shared frame of every kind and for a
# sequence shared frame by frame; a failing rank ends the job with one
# line, a failure status and no output.
# Usage: mpi_render_test.sh SHADETREE SOURCE_DIR
set -uo pipefail
shadetree="$1"
graphs="$2/graphs"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# Open MPI refuses to run as root unless told (CI containers run as root).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Shared memory between the ranks, and no single-copy transfers (which
# containers often forbid, with a warning per message).
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
# EXR files record when they were written; this makes them byte-comparable.
export SOURCE_DATE_EPOCH=1700000000
ranks=(mpirun -q -n 2 --oversubscribe)
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

# One frame shared by tile: a texture, a surface, volumes (cached shadows
# over a floor; empty space skipped), an environment.
for graph in marble donut_bumpy cloud_over_floor tribble sunset_sky; do
  for format in png exr; do
    "$shadetree" render "$graphs/$graph.json" -o "$work/one_$graph.$format" --size 96x64 --threads 2 2> /dev/null ||
      fail "$graph: the single process failed"
    "${ranks[@]}" "$shadetree" render "$graphs/$graph.json" -o "$work/two_$graph.$format" --size 96x64 --threads 1 \
      2> "$work/log" || fail "$graph: mpirun failed: $(cat "$work/log")"
    cmp -s "$work/one_$graph.$format" "$work/two_$graph.$format" || fail "$graph.$format: two ranks wrote other bytes"
  done
  grep -q "2 ranks, tiles [0-9]* + [0-9]*" "$work/log" || fail "$graph: the render line does not give the ranks' tiles"
done

# A sequence shared frame by frame: the same files, each frame rendered once.
mkdir -p "$work/one" "$work/two"
"$shadetree" render "$graphs/fireball.json" -o "$work/one/f.png" --size 48x48 --frames 1-9x2 2> /dev/null
"${ranks[@]}" "$shadetree" render "$graphs/fireball.json" -o "$work/two/f.png" --size 48x48 --frames 1-9x2 \
  --threads 1 2> "$work/log" || fail "sequence: mpirun failed"
for frame in 0001 0003 0005 0007 0009; do
  cmp -s "$work/one/f.$frame.png" "$work/two/f.$frame.png" || fail "sequence: frame $frame differs"
done
[ "$(grep -c -- '-> ' "$work/log")" = 5 ] || fail "sequence: not 5 frame lines: $(cat "$work/log")"
grep -q "rank 1 of 2" "$work/log" || fail "sequence: rank 1 rendered no frame"

# A frame a rank cannot write (a folder is in the way): one error line,
# status 1, and the job stops handing out frames.
mkdir -p "$work/broken/f.0005.png"
"${ranks[@]}" "$shadetree" render "$graphs/marble.json" -o "$work/broken/f.png" --size 32x32 --frames 1-9x2 \
  --threads 1 2> "$work/log"
status=$?
[ "$status" = 1 ] || fail "a failed frame: exit status $status"
[ "$(grep -c '^error: ' "$work/log")" = 1 ] || fail "a failed frame: not one error line: $(cat "$work/log")"
grep -q 'error: output ".*f.0005.png": cannot rename' "$work/log" || fail "a failed frame: $(cat "$work/log")"

# A shared frame rank 0 cannot write: status 1, one line, no file.
mkdir -p "$work/taken.png"
"${ranks[@]}" "$shadetree" render "$graphs/marble.json" -o "$work/taken.png" --size 32x32 2> "$work/log"
status=$?
[ "$status" = 1 ] || fail "an unwritable frame: exit status $status"
[ "$(wc -l < "$work/log")" = 1 ] || fail "an unwritable frame: not one line: $(cat "$work/log")"
[ -z "$(find "$work" -maxdepth 1 -name '.taken*')" ] || fail "an unwritable frame left a temporary file"

# A graph every rank refuses: its error once, with its status (2).
"${ranks[@]}" "$shadetree" render "$graphs/marble.json" -o "$work/x.png" --set nosuch=1 2> "$work/log"
status=$?
[ "$status" = 2 ] || fail "a bad --set: exit status $status"
[ "$(wc -l < "$work/log")" = 1 ] || fail "a bad --set: not one line: $(cat "$work/log")"

[ "$failures" = 0 ] && echo "mpi_render_test: all passed"
exit $((failures > 0))
