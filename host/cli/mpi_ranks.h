// `mpirun -np N prism render ...`: in a build with MPI (cmake -DPRISM_MPI=ON, or
// auto where OpenMPI is found) the ranks share each frame through
// prismSetFrameParts, each on its own devices; rank 0 writes the image and
// prints the report. MPI starts only in a process mpirun launched, so a plain
// `prism render` needs no MPI at run time.
#pragma once

#include <cstdint>

#include "prism.h"
#include "frame_deal.h"

namespace prism_cli {

struct Ranks {
  std::uint32_t rank = 0;
  std::uint32_t size = 1;
  bool shared() const { return size > 1; }
};

// Starts MPI once if mpirun launched this process; a single rank otherwise.
// Throws UsageError when mpirun launched several ranks of a build without MPI
// (each would render and write the whole frame).
Ranks startRanks();
// The frame parts for prismSetFrameParts: every rank sharing each frame (one
// part alone without MPI).
PrismFrameParts frameParts(const Ranks& ranks);
// The frame parts of the group of ranks that shares one of an animation's last
// frames (deal.shares; dealFrames), over a communicator of their own.
// Collective: every rank calls it once, before rendering anything, when the
// deal leaves frames over (a rank that shares none gets one part alone). Until
// sharedPartRendered, a failure of this rank ends the run (endRanks), since the
// others of its group would wait for its part.
PrismFrameParts groupFrameParts(const FrameDeal& deal);
// Says the group's frame is rendered (prismRender returned, every part's share
// in): a failure after it, such as a write, leaves no one waiting.
void sharedPartRendered();
// Says the shared frame is rendered: the ranks wait for each other no more.
void frameRendered();
// Says the ranks render whole frames each (an animation's): none waits for
// another while rendering, so one that fails stops alone (unless it owes a
// part of a shared frame, groupFrameParts); at the end (endRanks) every rank
// waits for all, so that mpirun ends none of them early.
void ranksWorkAlone();
// Ends MPI. With several ranks, a failure (exit code not 0) before the frame was
// rendered, or before this rank's part of a shared frame, ends every rank
// (MPI_Abort), since the others would wait for this one forever; after it
// (rank 0's --check-nan finding, a write that fails) the code is returned as
// it is. Returns `code`.
int endRanks(int code);

}  // namespace prism_cli
