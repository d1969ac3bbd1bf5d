// `prism-bench mpi`: one frame rendered by `prism render` alone and under
// `mpirun -np N` for each N asked, the runs taking turns; the wall time and
// prism's own tracing time of each (medians), each rank count's speed against
// one process, and whether every image is the same bit for bit.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

// `prism-bench mpi ARGS...` (args[0] is "mpi"); 0 with a message when prism was
// built without MPI.
int mpiMain(const std::vector<std::string>& args);

}  // namespace prism::bench
