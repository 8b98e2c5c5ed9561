#!/usr/bin/env bash
# shadetree render under a real mpirun (Open MPI): two ranks write exactly
# the bytes one process writes, for a shared frame of every kind and for
# sequences shared frame by frame, resumed chunks included; a failing rank
# ends the job with one line, a failure status and no output.
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
# Under the sanitizer build the ranks check all but leaks: Open MPI's
# threads keep allocations past MPI_Finalize, from frames LeakSanitizer
# cannot name (so no suppression matches them). The single-process runs
# here, and the rest of the suite, check leaks as ever.
ranks=(env "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" mpirun -q -n 2 --oversubscribe)
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

# A 1024x1024 frame of each kind shared by tile.
for graph in marble donut_bumpy fireball; do
  "$shadetree" render "$graphs/$graph.json" -o "$work/one_$graph.1024.png" --size 1024x1024 2> /dev/null
  "${ranks[@]}" "$shadetree" render "$graphs/$graph.json" -o "$work/two_$graph.1024.png" --size 1024x1024 \
    --threads 1 2> "$work/log" || fail "$graph at 1024x1024: mpirun failed: $(cat "$work/log")"
  cmp -s "$work/one_$graph.1024.png" "$work/two_$graph.1024.png" || fail "$graph at 1024x1024: other bytes"
done

# Sequences of each kind shared frame by frame: the same files, each frame
# rendered once.
for graph in marble donut_bumpy fireball; do
  mkdir -p "$work/one_$graph" "$work/two_$graph"
  "$shadetree" render "$graphs/$graph.json" -o "$work/one_$graph/f.####.png" --size 48x48 --frames 0..7 2> /dev/null
  "${ranks[@]}" "$shadetree" render "$graphs/$graph.json" -o "$work/two_$graph/f.####.png" --size 48x48 \
    --frames 0..7 --threads 1 2> "$work/log" || fail "$graph sequence: mpirun failed"
  for frame in 0000 0001 0002 0003 0004 0005 0006 0007; do
    cmp -s "$work/one_$graph/f.$frame.png" "$work/two_$graph/f.$frame.png" || fail "$graph sequence: frame $frame"
  done
  [ "$(grep -c -- '-> ' "$work/log")" = 8 ] || fail "$graph sequence: not 8 frame lines: $(cat "$work/log")"
done
# Both ranks take frames. (At 48x48 a busy machine can let one rank claim
# all 8 frames of a cheap graph before the other has started; fireball at
# 192x192 takes long enough a frame that it cannot.)
"${ranks[@]}" "$shadetree" render "$graphs/fireball.json" -o "$work/shared.####.png" --size 192x192 \
  --frames 0..7 --threads 1 2> "$work/log" || fail "shared sequence: mpirun failed"
grep -q "rank 1 of 2" "$work/log" || fail "shared sequence: rank 1 rendered no frame: $(cat "$work/log")"

# A chunk of a stepped list, resumed: the frames that exist stay as they
# are, and the chunk's others are written once.
mkdir -p "$work/resume"
"$shadetree" render "$graphs/marble.json" -o "$work/resume/f.png" --size 32x32 --frames 1-20x3 --chunk 4-13 \
  2> /dev/null
rm "$work/resume/f.0007.png"
touch -d '2001-01-01' "$work/resume/f.0004.png"
"${ranks[@]}" "$shadetree" render "$graphs/marble.json" -o "$work/resume/f.png" --size 32x32 --frames 1-20x3 \
  --chunk 4-13 --skip-existing --threads 1 2> "$work/log" || fail "resume: mpirun failed"
[ "$(ls "$work/resume")" = "$(printf 'f.0004.png\nf.0007.png\nf.0010.png\nf.0013.png')" ] ||
  fail "resume: $(ls "$work/resume")"
[ "$(grep -c -- '-> ' "$work/log")" = 1 ] || fail "resume: not one frame rendered: $(cat "$work/log")"
[ "$(stat -c %Y "$work/resume/f.0004.png")" = "$(date -d '2001-01-01' +%s)" ] || fail "resume: f.0004 was rewritten"

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
