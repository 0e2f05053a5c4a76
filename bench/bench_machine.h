// bench_machine.h - what the machine itself gives two threads: the ceilings against which the MPM cases'
// two-thread speed-ups (bench_step.cpp) are read.
//
//   machine_fma/T     T threads each run 16 independent chains of scalar multiply-adds (no memory traffic,
//                     no synchronisation inside the timed loop): pure core throughput.
//   machine_triad/T   T threads each run the STREAM triad a = b + s c over their own three arrays of 128 MB
//                     (far out of cache): memory bandwidth.
// Both report their rate per second summed over the threads (fma: multiply-adds; triad: bytes). On a machine
// whose cores are its own, T = 2 gives twice T = 1. On a virtual machine whose host shares its cores or memory
// with other guests, it does not, and no program can scale better than these loops do at that moment; run
// them interleaved with the MPM cases (--benchmark_enable_random_interleaving=true) so that both see the
// same host.
#pragma once

#include <benchmark/benchmark.h>
#include <omp.h>

#include <vector>

namespace cdmpm::bench {

inline void machine_fma(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  constexpr int chains = 16;
  constexpr long per_thread = 50'000'000;  // iterations of the 16 chains
  double sink = 0;
  for (auto _ : state) {
#pragma omp parallel num_threads(threads) reduction(+ : sink)
    {
      volatile double va = 0.999999999, vb = 1e-9;  // opaque to the optimiser
      const double a = va, b = vb;
      double acc[chains];
      for (int c = 0; c < chains; ++c) acc[c] = 1.0 + c * 1e-9;
      for (long i = 0; i < per_thread; ++i)
        for (int c = 0; c < chains; ++c) {
          acc[c] = acc[c] * a + b;
          asm volatile("" : "+x"(acc[c]));  // keeps every multiply-add
        }
      for (double x : acc) sink += x;
    }
  }
  benchmark::DoNotOptimize(sink);
  state.counters["fma_per_second"] = benchmark::Counter(
      double(threads) * chains * per_thread * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

inline void machine_triad(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  constexpr size_t n = size_t(16) << 20;  // doubles per array: 128 MB
  std::vector<std::vector<double>> A(threads), B(threads), C(threads);
#pragma omp parallel num_threads(threads)
  {  // each thread touches its own arrays first (first-touch placement)
    const int t = omp_get_thread_num();
    A[t].assign(n, 1.0), B[t].assign(n, 2.0), C[t].assign(n, 3.0);
  }
  for (auto _ : state) {
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num();
      double* a = A[t].data();
      const double *b = B[t].data(), *c = C[t].data();
      for (size_t k = 0; k < n; ++k) a[k] = b[k] + 0.5 * c[k];
    }
    benchmark::ClobberMemory();
  }
  state.counters["bytes_per_second"] = benchmark::Counter(
      double(threads) * 3 * sizeof(double) * n * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

inline void register_machine_cases() {
  for (auto* b : {benchmark::RegisterBenchmark("machine_fma", machine_fma),
                  benchmark::RegisterBenchmark("machine_triad", machine_triad)})
    b->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
}

}  // namespace cdmpm::bench
