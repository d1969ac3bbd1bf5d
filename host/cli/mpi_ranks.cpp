#include "mpi_ranks.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "args.h"

#ifdef PRISM_WITH_MPI
#include <mpi.h>
#endif

namespace prism_cli {
namespace {

PrismFrameParts partsAlone() {
  PrismFrameParts parts{};
  parts.struct_size = sizeof parts;
  parts.parts = 1;
  return parts;
}

// Set by mpirun (OpenMPI), or by other launchers through PMI/PMIx.
std::uint32_t launchedRanks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* value = std::getenv(name)) return static_cast<std::uint32_t>(std::strtoul(value, nullptr, 10));
  }
  return 0;
}

#ifdef PRISM_WITH_MPI
bool g_started = false;
bool g_rendered = false;
bool g_alone = false;  // ranks render whole frames each (ranksWorkAlone)
bool g_owes_part = false;  // this rank has yet to render its part of a shared frame
Ranks g_ranks;
MPI_Comm g_comm = MPI_COMM_NULL;  // prism's own, so that its tags meet no one else's

bool g_serialized = false;  // MPI_THREAD_SERIALIZED: the devices' threads may call it, one at a time
// Held for every MPI call made while a WindowProgress thread may run: those of
// the frame parts' callbacks, which are all prismRender makes (the main thread
// makes the others before or after a render, when none runs).
std::mutex g_calls;

// Calls MPI every kProgressEvery on the window owner's behalf while a frame's
// units are dealt. Where the network does not do remote atomics itself (plain TCP, or
// any transport where Open MPI falls back to its pt2pt one-sided component),
// another rank's compare-and-swap on rank 0's words completes only while rank
// 0 is inside MPI. Rank 0 calls MPI once a unit it takes, so the others waited
// for its units: on loopback over TCP, rank 1 took 7 of 57 units and was busy
// 0.27 s of 1.1 (docs/devices.md). An MPI_Iprobe drives the progress engine
// without taking any message.
class WindowProgress {
 public:
  explicit WindowProgress(MPI_Comm comm) : m_thread([this, comm] { run(comm); }) {}
  ~WindowProgress() {
    m_stop = true;
    m_thread.join();
  }
  WindowProgress(const WindowProgress&) = delete;
  WindowProgress& operator=(const WindowProgress&) = delete;

 private:
  static constexpr std::chrono::microseconds kProgressEvery{250};
  void run(MPI_Comm comm) {
    while (!m_stop) {
      {
        std::lock_guard<std::mutex> lock(g_calls);
        int flag = 0;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &flag, MPI_STATUS_IGNORE);
      }
      std::this_thread::sleep_for(kProgressEvery);
    }
  }
  std::atomic<bool> m_stop{false};
  std::thread m_thread;
};

// The ranks sharing a frame, as PrismFrameParts.user: all of them (a still), or
// a group sharing one of an animation's last frames.
struct PartsComm {
  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0, size = 1;
  // PrismFrameParts.compare_swap's words, one a rank, on the communicator's
  // rank 0 (MPI_WIN_NULL where some rank has too few of MPI's threads for the
  // dealing, or MPI could not make the window: openWords).
  MPI_Win words = MPI_WIN_NULL;
  // On rank 0, from its first compare-and-swap of a frame (the deal has begun)
  // to the next exchange (the deal is over, and a blocking exchange drives
  // MPI's progress itself).
  std::unique_ptr<WindowProgress> progress;
};
PartsComm g_all, g_group;

// MPI counts in int: large exchanges go in pieces.
constexpr std::uint64_t kPiece = 1u << 30;

void sendBytes(MPI_Comm comm, const void* data, std::uint64_t size, int to) {
  MPI_Send(&size, 1, MPI_UINT64_T, to, 0, comm);
  const auto* bytes = static_cast<const char*>(data);
  for (std::uint64_t at = 0; at < size; at += kPiece)
    MPI_Send(bytes + at, static_cast<int>(std::min(kPiece, size - at)), MPI_BYTE, to, 1, comm);
}

std::vector<char> receiveBytes(MPI_Comm comm, int from) {
  std::uint64_t size = 0;
  MPI_Recv(&size, 1, MPI_UINT64_T, from, 0, comm, MPI_STATUS_IGNORE);
  std::vector<char> bytes(size);
  for (std::uint64_t at = 0; at < size; at += kPiece)
    MPI_Recv(bytes.data() + at, static_cast<int>(std::min(kPiece, size - at)), MPI_BYTE, from, 1, comm,
             MPI_STATUS_IGNORE);
  return bytes;
}

void broadcastBytes(MPI_Comm comm, std::vector<char>& bytes, int root) {
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, root, comm);
  bytes.resize(size);
  for (std::uint64_t at = 0; at < size; at += kPiece)
    MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(kPiece, size - at)), MPI_BYTE, root, comm);
}

// PrismFrameParts.exchange over the PartsComm in `user`. MPI's own errors end
// the run (MPI_ERRORS_ARE_FATAL), so a return here is a success.
int exchange(void* user, int to_all, const void* data, std::uint64_t size, PrismReceiveFn receive, void* receiver) {
  PartsComm& parts = *static_cast<PartsComm*>(user);
  parts.progress.reset();  // the deal is over (prismRender exchanges after it, on this thread)
  std::lock_guard<std::mutex> lock(g_calls);
  if (to_all) {
    for (int p = 0; p < parts.size; ++p) {
      std::vector<char> bytes;
      if (p == parts.rank) bytes.assign(static_cast<const char*>(data), static_cast<const char*>(data) + size);
      broadcastBytes(parts.comm, bytes, p);
      receive(receiver, static_cast<std::uint32_t>(p), bytes.data(), bytes.size());
    }
    return 0;
  }
  if (parts.rank != 0) {
    sendBytes(parts.comm, data, size, 0);
    return 0;
  }
  receive(receiver, 0, data, size);
  for (int p = 1; p < parts.size; ++p) {
    const std::vector<char> bytes = receiveBytes(parts.comm, p);
    receive(receiver, static_cast<std::uint32_t>(p), bytes.data(), bytes.size());
  }
  return 0;
}

// PrismFrameParts.compare_swap: on the words in rank 0's window, which every
// rank holds open (passive target), so rank 0 never waits on a request: the
// ranks deal the frame's units among themselves as their devices come free.
int compareSwap(void* user, std::uint32_t word, std::uint64_t expected, std::uint64_t desired, std::uint64_t* found) {
  PartsComm& parts = *static_cast<PartsComm*>(user);
  std::lock_guard<std::mutex> lock(g_calls);  // prismRender never calls it twice at once
  if (parts.rank == 0 && !parts.progress) parts.progress = std::make_unique<WindowProgress>(parts.comm);
  MPI_Compare_and_swap(&desired, &expected, found, MPI_UINT64_T, 0, static_cast<MPI_Aint>(word), parts.words);
  MPI_Win_flush(0, parts.words);
  return 0;
}

// Collective over comm: the words, zero before any rank swaps one. Where MPI
// cannot make the window on every rank (no one-sided support for this
// network), no rank uses it: each traces its own stretch.
void openWords(PartsComm& comm) {
  if (!g_serialized) return;  // the same on every rank (startRanks)
  std::uint64_t* base = nullptr;
  const MPI_Aint bytes = comm.rank == 0 ? static_cast<MPI_Aint>(comm.size) * 8 : 0;
  MPI_Comm_set_errhandler(comm.comm, MPI_ERRORS_RETURN);
  const int made = MPI_Win_allocate(bytes, 8, MPI_INFO_NULL, comm.comm, &base, &comm.words) == MPI_SUCCESS ? 1 : 0;
  MPI_Comm_set_errhandler(comm.comm, MPI_ERRORS_ARE_FATAL);
  int everywhere = 0;
  MPI_Allreduce(&made, &everywhere, 1, MPI_INT, MPI_MIN, comm.comm);
  if (!everywhere) {
    // Not freed: MPI_Win_free would wait for the ranks that have none.
    comm.words = MPI_WIN_NULL;
    return;
  }
  MPI_Win_lock_all(0, comm.words);
  if (comm.rank == 0) {
    const std::uint64_t zero = 0;
    std::uint64_t was = 0;
    for (int w = 0; w < comm.size; ++w)
      MPI_Fetch_and_op(&zero, &was, MPI_UINT64_T, 0, w, MPI_REPLACE, comm.words);
    MPI_Win_flush(0, comm.words);
  }
  MPI_Barrier(comm.comm);
}

// Collective over comm, where every rank of it ends normally.
void closeWords(PartsComm& comm) {
  if (comm.words == MPI_WIN_NULL) return;
  comm.progress.reset();
  MPI_Win_unlock_all(comm.words);
  MPI_Win_free(&comm.words);
}

PrismFrameParts partsOver(PartsComm& comm) {
  PrismFrameParts parts{};
  parts.struct_size = sizeof parts;
  parts.part = static_cast<std::uint32_t>(comm.rank);
  parts.parts = static_cast<std::uint32_t>(comm.size);
  if (comm.size > 1) {
    parts.exchange = exchange;
    parts.user = &comm;
    openWords(comm);
    if (comm.words != MPI_WIN_NULL) parts.compare_swap = compareSwap;
  }
  return parts;
}
#endif

}  // namespace

#ifdef PRISM_WITH_MPI
Ranks startRanks() {
  if (g_started || launchedRanks() == 0) return g_ranks;
  // This thread calls MPI, and so do the devices' threads when they take units
  // (compareSwap), one at a time; PoCL's threads do not. Where MPI offers
  // only this thread, each rank traces a fixed stretch of the frame.
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
  g_started = true;
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    g_started = false;
    throw std::runtime_error("MPI offers no threads beside its calls (MPI_THREAD_FUNNELED), which prism needs");
  }
  MPI_Comm_dup(MPI_COMM_WORLD, &g_comm);
  // Every rank deals the same way, or the window's making would wait for some.
  int lowest = provided;
  MPI_Allreduce(&provided, &lowest, 1, MPI_INT, MPI_MIN, g_comm);
  g_serialized = lowest >= MPI_THREAD_SERIALIZED;
  int rank = 0, size = 1;
  MPI_Comm_rank(g_comm, &rank);
  MPI_Comm_size(g_comm, &size);
  g_ranks.rank = static_cast<std::uint32_t>(rank);
  g_ranks.size = static_cast<std::uint32_t>(size);
  g_all.comm = g_comm;
  g_all.rank = rank;
  g_all.size = size;
  return g_ranks;
}

PrismFrameParts frameParts(const Ranks& ranks) {
  if (!g_started || !ranks.shared()) return partsAlone();
  return partsOver(g_all);
}

PrismFrameParts groupFrameParts(const FrameDeal& deal) {
  if (!g_started) return partsAlone();
  MPI_Comm_split(g_comm, deal.shares ? static_cast<int>(deal.group) : MPI_UNDEFINED, static_cast<int>(g_ranks.rank),
                 &g_group.comm);
  if (!deal.shares) return partsAlone();
  MPI_Comm_rank(g_group.comm, &g_group.rank);
  MPI_Comm_size(g_group.comm, &g_group.size);
  g_owes_part = g_group.size > 1;  // before anything can fail: the group waits for this rank
  if (static_cast<std::uint32_t>(g_group.rank) != deal.group_part ||
      static_cast<std::uint32_t>(g_group.size) != deal.group_parts)
    throw std::logic_error("MPI made a group other than the frame deal's");
  return partsOver(g_group);
}

void frameRendered() { g_rendered = true; }
void sharedPartRendered() { g_owes_part = false; }
void ranksWorkAlone() {
  g_rendered = true;
  g_alone = true;
}

int endRanks(int code) {
  if (!g_started) return code;
  // From here only this thread calls MPI.
  g_all.progress.reset();
  g_group.progress.reset();
  // So does one that fails before its part of a frame it shares with others.
  if (code != 0 && g_ranks.shared() && (!g_rendered || g_owes_part)) MPI_Abort(MPI_COMM_WORLD, code);
  // Ranks that work alone wait for each other before any exits: mpirun ends
  // the whole job when one rank exits with a failure, frames half done.
  if (g_alone && g_ranks.shared()) {
    int worst = 0;
    MPI_Allreduce(&code, &worst, 1, MPI_INT, MPI_MAX, g_comm);
  }
  closeWords(g_all);
  closeWords(g_group);
  if (g_group.comm != MPI_COMM_NULL) MPI_Comm_free(&g_group.comm);
  MPI_Comm_free(&g_comm);
  MPI_Finalize();
  g_started = false;
  return code;
}
#else
Ranks startRanks() {
  if (launchedRanks() > 1)
    throw UsageError("mpirun started " + std::to_string(launchedRanks()) +
                     " ranks, but this prism was built without MPI (configure with -DPRISM_MPI=ON and "
                     "install libopenmpi-dev), so each would render the whole frame; run it alone");
  return Ranks{};
}

void frameRendered() {}
void ranksWorkAlone() {}
PrismFrameParts frameParts(const Ranks&) { return partsAlone(); }
PrismFrameParts groupFrameParts(const FrameDeal&) { return partsAlone(); }
void sharedPartRendered() {}

int endRanks(int code) { return code; }
#endif

}  // namespace prism_cli
