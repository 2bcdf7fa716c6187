#!/usr/bin/env bash
# A distributed run against one process (docs/cluster.md):
#   mpi_same_bits.sh same IMPACT3D DECK NP WORKDIR
#     runs DECK with one process and with mpirun -np NP (one thread each) and compares the plot
#     database d3plot*, the time histories d3thdt* and the ASCII files (glstat, matsum, nodout,
#     elout, rwforc) byte for byte; d3hsp must state the partition over NP ranks and, but for
#     that statement and its clock readings, be the one process's d3hsp line for line.
#   mpi_same_bits.sh same IMPACT3D DECK NP WORKDIR EXPECT
#     the same, and both d3hsp must have a line that matches the extended regular expression
#     EXPECT (what the deck is there to show, e.g. a run check's message).
#   mpi_same_bits.sh restart IMPACT3D DECK NP WORKDIR CYCLES
#     DECK with a restart dump every CYCLES cycles (*DATABASE_BINARY_D3DUMP added): one process
#     and mpirun -np NP write the same dumps byte for byte; then mpirun -np NP restarts from the
#     first dump (r=d3dump01) and its plot database, time histories, ASCII files and dumps are the
#     uninterrupted one process's byte for byte.
#   mpi_same_bits.sh refused IMPACT3D DECK NP WORKDIR
#     the deck must be refused under mpirun -np NP: exit code 3 and message 3007.
set -uo pipefail
mode=$1 impact3d=$2 deck=$3 np=$4 work=$5 expect=${6:-}
flags=(--oversubscribe)
[ "$(id -u)" = 0 ] && flags+=(--allow-run-as-root)
# ranks that wait yield the core (this machine runs more ranks than it has cores)
export SOURCE_DATE_EPOCH=0 OMPI_MCA_mpi_yield_when_idle=1
rm -rf "$work"
mkdir -p "$work/one" "$work/np$np"
if [ "$mode" = refused ]; then
  (cd "$work/np$np" && mpirun "${flags[@]}" -np "$np" "$impact3d" i="$deck" ncpu=1 > log 2>&1)
  rc=$?
  cat "$work/np$np/log"
  [ $rc = 3 ] || { echo "exit code $rc, not 3"; exit 1; }
  grep -q "error 3007" "$work/np$np/log" || { echo "no message 3007"; exit 1; }
  echo "refused as expected on $np ranks"
  exit 0
fi
if [ "$mode" = restart ]; then
  cycles=$6
  sed "1a *DATABASE_BINARY_D3DUMP\\n$(printf '%10d' "$cycles")" "$deck" > "$work/deck.k"
  (cd "$work/one" && "$impact3d" i=../deck.k ncpu=1 > log 2>&1) || { cat "$work/one/log"; echo "one process failed"; exit 1; }
  (cd "$work/np$np" && mpirun "${flags[@]}" -np "$np" "$impact3d" i=../deck.k ncpu=1 > log 2>&1) ||
    { cat "$work/np$np/log"; echo "mpirun -np $np failed"; exit 1; }
  [ -e "$work/one/d3dump01" ] || { echo "no restart dump d3dump01"; exit 1; }
  n=0
  for f in "$work/one"/d3dump*; do
    n=$((n + 1))
    cmp "$f" "$work/np$np/$(basename "$f")" || { echo "differs: $(basename "$f") of the first run"; exit 1; }
  done
  echo "the same $n restart dumps, one process and $np ranks"
  (cd "$work/np$np" && mpirun "${flags[@]}" -np "$np" "$impact3d" r=d3dump01 ncpu=1 > rlog 2>&1) ||
    { cat "$work/np$np/rlog"; echo "mpirun -np $np r=d3dump01 failed"; exit 1; }
  grep -q "restart from d3dump01 at cycle $cycles" "$work/np$np/d3hsp" || { echo "d3hsp does not state the restart"; exit 1; }
  n=0
  for f in "$work/one"/d3plot* "$work/one"/d3thdt* "$work/one"/d3dump* "$work/one"/{glstat,matsum,nodout,elout,rwforc}; do
    [ -e "$f" ] || continue
    n=$((n + 1))
    cmp "$f" "$work/np$np/$(basename "$f")" || { echo "differs after the restart: $(basename "$f")"; exit 1; }
  done
  grep "N o r m a l" "$work/np$np/rlog"
  echo "same bits after a restart: $n files, one process and $np ranks"
  exit 0
fi
(cd "$work/one" && "$impact3d" i="$deck" ncpu=1 > log 2>&1) || { cat "$work/one/log"; echo "one process failed"; exit 1; }
(cd "$work/np$np" && mpirun "${flags[@]}" -np "$np" "$impact3d" i="$deck" ncpu=1 > log 2>&1) ||
  { cat "$work/np$np/log"; echo "mpirun -np $np failed"; exit 1; }
n=0
for f in "$work/one"/d3plot* "$work/one"/d3thdt* "$work/one"/{glstat,matsum,nodout,elout,rwforc}; do
  [ -e "$f" ] || continue
  n=$((n + 1))
  cmp "$f" "$work/np$np/$(basename "$f")" || { echo "differs: $(basename "$f")"; exit 1; }
done
# the printed file without its clock readings (the cycle lines' last two columns, the timings) and
# without what only a distributed run states (the partition, its communication time)
numbers() {
  sed -E -e 's/^( +[0-9]+ +[-0-9.e+]+ +[-0-9.e+]+ +[0-9]+ +[-0-9.e+]+) +[0-9.]+ +[-0-9.]+$/\1/' \
         -e '/^ cycles [0-9]+, elapsed/d' -e '/^ phase times/d' -e '/^ communication on rank 0/d' \
         -e '/^ distributed run: /,/^   imbalance/d' "$1"
}
diff -B <(numbers "$work/one/d3hsp") <(numbers "$work/np$np/d3hsp") || { echo "differs: d3hsp"; exit 1; }
n=$((n + 1))
if [ -n "$expect" ]; then
  for d in one "np$np"; do
    grep -E -m 1 "$expect" "$work/$d/d3hsp" || { echo "no line of $d/d3hsp matches: $expect"; exit 1; }
  done
fi
count() { ls "$1" | grep -c -E '^(d3plot|d3thdt)'; }
[ "$(count "$work/one")" = "$(count "$work/np$np")" ] || { echo "not the same number of database files"; exit 1; }
grep -A $((np + 2)) "distributed run: $np MPI ranks" "$work/np$np/d3hsp" || { echo "d3hsp does not state the partition"; exit 1; }
grep "elapsed" "$work/one/log" "$work/np$np/log"
echo "same bits: $n files, one process and $np ranks"
