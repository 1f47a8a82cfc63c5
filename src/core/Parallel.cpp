#include "core/Parallel.hpp"

#include <omp.h>

namespace poro::parallel {

void setThreads(int n) { omp_set_num_threads(n < 1 ? 1 : n); }

int threads() { return omp_get_max_threads(); }

int threadIndex() { return omp_get_thread_num(); }

} // namespace poro::parallel
