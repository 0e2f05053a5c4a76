// communicator.h - the processes of a distributed run (MPI, built with -DCDMPM_MPI=ON; docs/architecture.md): rank,
// size, collective maxima, minima and sums, the exchange of byte buffers between ranks, the gather to rank 0, and
// an abort that names the rank. Only parallel/reduction.h and the distributed step (parallel/domain.h) call it.
//
// Maxima and minima are exact in any order. A sum gathers every rank's partial sum and adds them in rank order
// (p0 + p1 + ... + p(N-1), starting from p0, not from 0, so one rank returns its partial sum unchanged, -0.0
// included): the result has the same bits on every rank and does not depend on the message timing.
// A program of the MPI build started without mpirun (or a test that never calls MPI_Init) is one process: every
// function then acts on that process alone. Inside a LocalScope the reductions are the identity on the calling
// process: rank 0 evaluates the outputs on the gathered particles of the whole run there (sim/simulation.h,
// with_whole_state), while the other ranks do not take part.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cdmpm::mpi {

using Bytes = std::vector<char>;

// MPI_Init and MPI_Finalize around main (one per program).
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

// True when MPI was initialised (the program runs under a Session).
bool active();
int rank();
int size();
// The number of ranks on this machine (sharing its memory; MPI_COMM_TYPE_SHARED).
int node_size();

// While a LocalScope exists, the reductions below act on the calling process alone.
class LocalScope {
 public:
  LocalScope();
  ~LocalScope();
  LocalScope(const LocalScope&) = delete;
  LocalScope& operator=(const LocalScope&) = delete;
};

double max(double local);
double min(double local);
double sum(double local);
// Element-wise over n values, in place.
void max(double* values, size_t n);
void min(double* values, size_t n);
void sum(double* values, size_t n);
void max(float* values, size_t n);
void min(float* values, size_t n);
void sum(float* values, size_t n);
// Integers: exact in any order.
void sum(int64_t* values, size_t n);

// Sends send[r] to rank r (send has size() entries; empty buffers are sent as nothing) and returns what every rank
// sent to this one, indexed by the sender's rank.
std::vector<Bytes> exchange(const std::vector<Bytes>& send);
// Every rank's buffer, in rank order, on every rank.
std::vector<Bytes> allgather(const Bytes& local);
// Every rank's buffer, in rank order, on rank 0 (an empty list elsewhere).
std::vector<Bytes> gather(const Bytes& local);

// Waits until every rank has called it.
void barrier();

// Prints "cdmpm: error (rank R of N): message" and ends every process of the run with exit code `code`.
[[noreturn]] void abort(const std::string& message, int code);

// Appends the bytes of a trivially copyable value or array to a buffer, and reads them back.
template <class T>
void put(Bytes& b, const T& value) {
  const char* p = reinterpret_cast<const char*>(&value);
  b.insert(b.end(), p, p + sizeof(T));
}
template <class T>
void put(Bytes& b, const T* values, size_t n) {
  const char* p = reinterpret_cast<const char*>(values);
  b.insert(b.end(), p, p + n * sizeof(T));
}
struct Reader {
  const Bytes& b;
  size_t at = 0;
  bool done() const { return at >= b.size(); }
  template <class T>
  T get() {
    T value;
    std::copy(b.data() + at, b.data() + at + sizeof(T), reinterpret_cast<char*>(&value));
    at += sizeof(T);
    return value;
  }
  template <class T>
  void get(T* values, size_t n) {
    std::copy(b.data() + at, b.data() + at + n * sizeof(T), reinterpret_cast<char*>(values));
    at += n * sizeof(T);
  }
};

}  // namespace cdmpm::mpi
