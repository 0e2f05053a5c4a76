// communicator.cpp - the MPI calls behind communicator.h (compiled only with -DCDMPM_MPI=ON).
#include "parallel/communicator.h"

#define OMPI_SKIP_MPICXX 1  // the C API only
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace cdmpm::mpi {
namespace {

int local_depth = 0;  // open LocalScopes

bool collective() { return active() && local_depth == 0 && size() > 1; }

template <class T>
MPI_Datatype type_of();
template <>
MPI_Datatype type_of<double>() { return MPI_DOUBLE; }
template <>
MPI_Datatype type_of<float>() { return MPI_FLOAT; }
template <>
MPI_Datatype type_of<int64_t>() { return MPI_INT64_T; }

template <class T>
void reduce(T* values, size_t n, MPI_Op op) {
  if (!collective() || n == 0) return;
  MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(n), type_of<T>(), op, MPI_COMM_WORLD);
}

// Every rank's n partial sums, added in rank order from rank 0's.
template <class T>
void sum_in_rank_order(T* values, size_t n) {
  if (!collective() || n == 0) return;
  const int p = size();
  std::vector<T> all(n * static_cast<size_t>(p));
  MPI_Allgather(values, static_cast<int>(n), type_of<T>(), all.data(), static_cast<int>(n), type_of<T>(), MPI_COMM_WORLD);
  for (size_t i = 0; i < n; ++i) {
    T s = all[i];
    for (int r = 1; r < p; ++r) s += all[static_cast<size_t>(r) * n + i];
    values[i] = s;
  }
}

std::vector<int> displacements(const std::vector<int>& counts, int& total) {
  std::vector<int> d(counts.size(), 0);
  total = 0;
  for (size_t r = 0; r < counts.size(); ++r) {
    d[r] = total;
    total += counts[r];
  }
  return d;
}

}  // namespace

Session::Session(int& argc, char**& argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
}
Session::~Session() { MPI_Finalize(); }

bool active() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}
int rank() {
  if (!active()) return 0;
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}
int size() {
  if (!active()) return 1;
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

int node_size() {
  if (!active()) return 1;
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int s = 1;
  MPI_Comm_size(node, &s);
  MPI_Comm_free(&node);
  return s;
}

LocalScope::LocalScope() { ++local_depth; }
LocalScope::~LocalScope() { --local_depth; }

double max(double local) { max(&local, 1); return local; }
double min(double local) { min(&local, 1); return local; }
double sum(double local) { sum(&local, 1); return local; }
void max(double* v, size_t n) { reduce(v, n, MPI_MAX); }
void min(double* v, size_t n) { reduce(v, n, MPI_MIN); }
void sum(double* v, size_t n) { sum_in_rank_order(v, n); }
void max(float* v, size_t n) { reduce(v, n, MPI_MAX); }
void min(float* v, size_t n) { reduce(v, n, MPI_MIN); }
void sum(float* v, size_t n) { sum_in_rank_order(v, n); }
void sum(int64_t* v, size_t n) { reduce(v, n, MPI_SUM); }

std::vector<Bytes> exchange(const std::vector<Bytes>& send) {
  const int p = size();
  if (!active() || p == 1) return {send.empty() ? Bytes{} : send[0]};
  std::vector<int> send_counts(p), recv_counts(p);
  for (int r = 0; r < p; ++r) send_counts[r] = static_cast<int>(send[r].size());
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int send_total = 0, recv_total = 0;
  const std::vector<int> sd = displacements(send_counts, send_total), rd = displacements(recv_counts, recv_total);
  Bytes out(send_total), in(recv_total);
  for (int r = 0; r < p; ++r) std::copy(send[r].begin(), send[r].end(), out.begin() + sd[r]);
  MPI_Alltoallv(out.data(), send_counts.data(), sd.data(), MPI_BYTE, in.data(), recv_counts.data(), rd.data(), MPI_BYTE,
                MPI_COMM_WORLD);
  std::vector<Bytes> received(p);
  for (int r = 0; r < p; ++r) received[r].assign(in.begin() + rd[r], in.begin() + rd[r] + recv_counts[r]);
  return received;
}

namespace {
std::vector<Bytes> gather_to(const Bytes& local, bool everywhere) {
  const int p = size();
  if (!active() || p == 1) return {local};
  int n = static_cast<int>(local.size());
  std::vector<int> counts(p);
  if (everywhere) MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  else MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  const std::vector<int> d = displacements(counts, total);
  Bytes all(everywhere || rank() == 0 ? total : 0);
  if (everywhere)
    MPI_Allgatherv(local.data(), n, MPI_BYTE, all.data(), counts.data(), d.data(), MPI_BYTE, MPI_COMM_WORLD);
  else
    MPI_Gatherv(local.data(), n, MPI_BYTE, all.data(), counts.data(), d.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
  if (!everywhere && rank() != 0) return {};
  std::vector<Bytes> out(p);
  for (int r = 0; r < p; ++r) out[r].assign(all.begin() + d[r], all.begin() + d[r] + counts[r]);
  return out;
}
}  // namespace

std::vector<Bytes> allgather(const Bytes& local) { return gather_to(local, true); }
std::vector<Bytes> gather(const Bytes& local) { return gather_to(local, false); }

void barrier() {
  if (active() && size() > 1) MPI_Barrier(MPI_COMM_WORLD);
}

void abort(const std::string& message, int code) {
  std::fprintf(stderr, "cdmpm: error (rank %d of %d): %s\n", rank(), size(), message.c_str());
  std::fflush(stderr);
  if (active() && size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace cdmpm::mpi
