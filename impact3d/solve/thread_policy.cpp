#include "impact3d/solve/thread_policy.h"

#include <unistd.h>

#include <cstdlib>

namespace impact3d {

void ensure_passive_openmp_wait(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
  // exec failed (no /proc): run on with the policy libgomp already chose
}

}  // namespace impact3d
