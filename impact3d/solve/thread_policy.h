#pragma once
// How the OpenMP threads wait for work.  By default libgomp spins for a while at every barrier
// and between parallel loops; on a shared machine a spinning thread takes a core from the thread
// that still works (on the 2-core development machine beside busy processes, two threads ran
// twice as slow as one).  The cycle has few parallel loops and each is long on the models that
// use threads, so sleeping costs little: impact3d runs with OMP_WAIT_POLICY=passive unless the
// user set OMP_WAIT_POLICY or GOMP_SPINCOUNT.  libgomp reads its environment when it is loaded,
// before main, so the program sets the variable and executes itself again, once (same process
// id, same arguments); if that fails it goes on with the default policy.

namespace impact3d {

void ensure_passive_openmp_wait(char** argv);

}  // namespace impact3d
