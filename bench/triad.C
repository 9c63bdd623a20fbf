// Memory bandwidth and floating-point rate of this machine, for the roofline estimates of
// bench/run: a STREAM-like triad a = b + s c (McCalpin's STREAM convention: 24 bytes moved
// per element, the write-allocate read not counted) on arrays of a given size, and a chain
// of independent multiply-adds compiled with the engine's own flags (what its scalar and
// auto-vectorised loops can reach). Threads: OMP_NUM_THREADS.
//
//     benchTriad [-size MiB] [-repeat n] [-flops] [-compiler]
//
// prints one line, e.g. "triad: 3 x 128 MiB, 2 threads, 21.4 GB/s (best of 10)"; -compiler
// names the compiler and flags it was built with (those of the engine).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#ifndef GPIC_CXX_FLAGS
#define GPIC_CXX_FLAGS "unknown"
#endif

namespace {

double seconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double triad(std::size_t mib, int repeat)
{
    const std::size_t n = mib * 1024 * 1024 / sizeof(double);
    // Not std::vector: its constructor would touch every page from one thread, and the
    // first touch decides where a page lives.
    double* a = static_cast<double*>(std::malloc(n * sizeof(double)));
    double* b = static_cast<double*>(std::malloc(n * sizeof(double)));
    double* c = static_cast<double*>(std::malloc(n * sizeof(double)));
    if (!a || !b || !c) {
        std::fprintf(stderr, "benchTriad: cannot allocate 3 x %zu MiB\n", mib);
        std::exit(1);
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        a[i] = 0.0;
        b[i] = 1.0;
        c[i] = 2.0;
    }
    const double s = 3.0;
    // Small arrays run many sweeps per timing, so that each timing lasts well above the clock's grain.
    const int sweeps = static_cast<int>(std::max<std::size_t>(1, (256u << 20) / (3 * n * sizeof(double))));
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeat; ++r) {
        const double t0 = seconds();
        // The same static split every sweep: each thread streams its own part, so the sweeps
        // need no barrier between them.
#pragma omp parallel
        for (int k = 0; k < sweeps; ++k) {
#pragma omp for schedule(static) nowait
            for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
        }
        best = std::min(best, (seconds() - t0) / sweeps);
    }
    volatile double keep = a[n / 2];
    (void)keep;
    std::free(a);
    std::free(b);
    std::free(c);
    return 3.0 * sizeof(double) * double(n) / best;
}

double multiplyAddRate(int repeat)
{
    // Sixteen independent chains per thread hide the latency of the adder; the values stay
    // bounded (x -> 0.5 x + 0.5 tends to 1), so no denormals or overflow slow it down.
    constexpr int chains = 16;
    const long iterations = 20000000;
    double best = std::numeric_limits<double>::infinity();
    double sink = 0;
    for (int r = 0; r < repeat; ++r) {
        const double t0 = seconds();
#pragma omp parallel reduction(+ : sink)
        {
            double x[chains];
            for (int k = 0; k < chains; ++k) x[k] = 1.0 + 0.01 * (k + omp_get_thread_num());
            const double m = 0.5, a = 0.5;
            for (long i = 0; i < iterations; ++i)
                for (int k = 0; k < chains; ++k) x[k] = m * x[k] + a;
            for (int k = 0; k < chains; ++k) sink += x[k];
        }
        best = std::min(best, seconds() - t0);
    }
    volatile double keep = sink;
    (void)keep;
    return 2.0 * chains * double(iterations) * omp_get_max_threads() / best;
}

} // namespace

int main(int argc, char* argv[])
{
    std::size_t mib = 128;
    int repeat = 10;
    bool flops = false, compiler = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-size" && i + 1 < argc) mib = std::strtoul(argv[++i], nullptr, 10);
        else if (arg == "-repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
        else if (arg == "-flops") flops = true;
        else if (arg == "-compiler") compiler = true;
        else {
            std::fprintf(stderr, "usage: benchTriad [-size MiB] [-repeat n] [-flops] [-compiler]\n");
            return 1;
        }
    }
    if (compiler) {
#if defined(__clang__)
        std::printf("compiler: clang %s, flags %s\n", __clang_version__, GPIC_CXX_FLAGS);
#elif defined(__GNUC__)
        std::printf("compiler: g++ %s, flags %s\n", __VERSION__, GPIC_CXX_FLAGS);
#else
        std::printf("compiler: unknown, flags %s\n", GPIC_CXX_FLAGS);
#endif
        return 0;
    }
    if (mib == 0) mib = 1;
    const int threads = omp_get_max_threads();
    if (flops)
        std::printf("multiply-add: %d threads, %.2f GFLOP/s (best of %d)\n", threads,
                    multiplyAddRate(repeat) / 1e9, repeat);
    else
        std::printf("triad: 3 x %zu MiB, %d threads, %.2f GB/s (best of %d)\n", mib, threads,
                    triad(mib, repeat) / 1e9, repeat);
    return 0;
}
