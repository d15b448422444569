// SPDX-License-Identifier: GPL-3.0-or-later
// rooflineProbe: this machine's double-precision peaks for the roofline of docs/benchmarks.md.
//
//   rooflineProbe [-threads 1,2] [-reps 9] [-mib 256] [-seconds 0.2]
//
// Compute: independent FMA chains a_k ← a_k b + c, k = 0 … Chains-1, in vectors of the widest
// width the build targets (8 doubles with AVX-512, 4 with AVX2) and, for the lower ceilings,
// in 4-wide vectors and scalars. Each FMA is 2 FLOP per lane. Chains = 16 independent vector
// accumulators hide the FMA latency (4 cycles × 2 pipes needs 8). Every lane of every chain
// is checked against the closed form a_n = bⁿ a_0 + c (1 − bⁿ)/(1 − b), so the compiler cannot
// have dropped work.
//
// Memory: STREAM-like kernels over three arrays of `mib` MiB each (≫ the L3), first touched
// by the threads that use them (static schedule):
//   read   s += a_i                      8 B per element read
//   write  b_i = s                       8 B (STREAM-like), 16 B with the write-allocate
//   copy   c_i = a_i                     16 B (STREAM), 24 B with the write-allocate
//   triad  a_i = b_i + s c_i             24 B (STREAM), 32 B with the write-allocate
// A store to a line that is not in the cache first reads the line (write-allocate, or read for
// ownership), unless the compiler emits non-temporal stores (GCC does not here, checked in the
// disassembly): the "+WA" figures count that read, i.e. the bytes that actually crossed the
// memory bus; the STREAM figures do not (STREAM's convention). The roofline uses triad+WA.
//
// Each figure is the median of `reps` timed repetitions (after one untimed warm-up), for each
// thread count. Prints a table and one machine-readable line per thread count:
//   ROOFLINE threads=<t> lanes=<w> gflops=<w-wide> gflops4=<4-wide> gflops1=<scalar>
//            readGBs=<..> writeGBs=<..> writeWAGBs=<..> copyGBs=<..> copyWAGBs=<..>
//            triadGBs=<..> triadWAGBs=<..>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

#if defined(__AVX512F__)
constexpr int WideLanes = 8;
#elif defined(__AVX__)
constexpr int WideLanes = 4;
#else
constexpr int WideLanes = 2;
#endif

constexpr int Chains = 16;

template <int Lanes> struct VecOf { typedef double type __attribute__((vector_size(8 * Lanes))); };
template <> struct VecOf<1> { typedef double type; };

/// Lane l of a vector (of a scalar: the scalar).
inline double lane(double x, int) {
    return x;
}
template <class V> inline double lane(const V& x, int l) {
    return x[l];
}

/// Keep each argument in a register as it is (no reassociation, no merging of chains into
/// wider vectors, no spilling of the chains to the stack).
template <class T> inline void opaque1(T& x) {
    asm volatile("" : "+v"(x));
}
template <class... T> inline void opaque(T&... x) {
    (opaque1(x), ...);
}

/// `iters` rounds of the Chains (16) FMA chains of `Lanes` lanes, held in 16 named registers;
/// returns the largest relative deviation of any lane from the closed form.
template <int Lanes> double fmaChains(long iters, double b, double c) {
    static_assert(Chains == 16, "fmaChains names its 16 chains");
    using V = typename VecOf<Lanes>::type;
    auto init = [](int k) { return V{} + 0.001 * (k + 1); };
    V a0 = init(0), a1 = init(1), a2 = init(2), a3 = init(3), a4 = init(4), a5 = init(5),
      a6 = init(6), a7 = init(7), a8 = init(8), a9 = init(9), a10 = init(10), a11 = init(11),
      a12 = init(12), a13 = init(13), a14 = init(14), a15 = init(15);
    V vb = V{} + b, vc = V{} + c;
    opaque(vb, vc);
    for (long it = 0; it < iters; ++it) {
        // 16 FMAs (-ffp-contract=fast), no chain depending on another.
        a0 = a0 * vb + vc, a1 = a1 * vb + vc, a2 = a2 * vb + vc, a3 = a3 * vb + vc;
        a4 = a4 * vb + vc, a5 = a5 * vb + vc, a6 = a6 * vb + vc, a7 = a7 * vb + vc;
        a8 = a8 * vb + vc, a9 = a9 * vb + vc, a10 = a10 * vb + vc, a11 = a11 * vb + vc;
        a12 = a12 * vb + vc, a13 = a13 * vb + vc, a14 = a14 * vb + vc, a15 = a15 * vb + vc;
        opaque(a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15);
    }
    const V acc[Chains] = {a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15};
    const double bn = std::pow(b, static_cast<double>(iters));
    double err = 0;
    for (int k = 0; k < Chains; ++k) {
        const double exact = bn * 0.001 * (k + 1) + c * (1.0 - bn) / (1.0 - b);
        for (int l = 0; l < Lanes; ++l)
            err = std::max(err, std::fabs(lane(acc[k], l) - exact) / std::fabs(exact));
    }
    return err;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Options {
    std::vector<int> threads{1, 2};
    int reps = 9;
    double mib = 256;
    double seconds = 0.2;
};

[[noreturn]] void usage(const std::string& error) {
    std::fprintf(stderr,
                 "rooflineProbe: %s\n\nUsage: rooflineProbe [-threads 1,2] [-reps 9] [-mib 256] "
                 "[-seconds 0.2]\n"
                 "  -threads  thread counts, comma-separated (each >= 1)\n"
                 "  -reps     timed repetitions per figure, the median is printed (>= 1)\n"
                 "  -mib      size of each of the three arrays of the memory kernels [MiB] "
                 "(>= 1; use several times the L3)\n"
                 "  -seconds  target time of one FMA repetition (> 0)\n",
                 error.c_str());
    std::exit(2);
}

double number(const char* key, const char* text) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(v))
        usage(std::string(key) + " expects a number, got '" + text + "'");
    return v;
}

Options parse(int argc, char* argv[]) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-help" || a == "-h" || a == "--help") {
            usage("measures peak FLOP/s and memory bandwidth");
        }
        if (i + 1 >= argc) usage(a + " needs a value");
        const char* v = argv[++i];
        if (a == "-threads") {
            o.threads.clear();
            std::stringstream ss(v);
            std::string item;
            while (std::getline(ss, item, ',')) {
                const double t = number("-threads", item.c_str());
                if (t < 1 || t != std::floor(t) || t > 1024)
                    usage("-threads expects whole numbers >= 1, got '" + item + "'");
                o.threads.push_back(static_cast<int>(t));
            }
            if (o.threads.empty()) usage("-threads expects at least one thread count");
        } else if (a == "-reps") {
            const double r = number("-reps", v);
            if (r < 1 || r != std::floor(r) || r > 1000)
                usage("-reps expects a whole number in [1, 1000], got " + std::string(v));
            o.reps = static_cast<int>(r);
        } else if (a == "-mib") {
            o.mib = number("-mib", v);
            if (!(o.mib >= 1 && o.mib <= 65536))
                usage("-mib expects a size in [1, 65536] MiB, got " + std::string(v));
        } else if (a == "-seconds") {
            o.seconds = number("-seconds", v);
            if (!(o.seconds > 0 && o.seconds <= 100))
                usage("-seconds expects a time in (0, 100], got " + std::string(v));
        } else {
            usage("unknown option " + a);
        }
    }
    return o;
}

bool checksOk = true;

/// GFLOP/s of the Lanes-wide FMA chains on all threads of the team (each thread its own
/// chains): median over reps of 2 Lanes Chains iters threads / wall time.
template <int Lanes> double flops(const Options& o, int threads) {
    constexpr double b = 0.999999, c = 1e-6;
    // Calibrate: iterations for about o.seconds on one thread.
    long iters = 1 << 16;
    while (true) {
        const double t0 = omp_get_wtime();
        fmaChains<Lanes>(iters, b, c);
        const double dt = omp_get_wtime() - t0;
        if (dt > 0.02 || iters > (1L << 40)) {
            iters = std::max(1L, static_cast<long>(iters * o.seconds / dt));
            break;
        }
        iters *= 4;
    }
    std::vector<double> rates;
    double worst = 0;
    for (int r = 0; r <= o.reps; ++r) { // r = 0: warm-up
        double err = 0;
        const double t0 = omp_get_wtime();
#pragma omp parallel num_threads(threads) reduction(max : err)
        err = fmaChains<Lanes>(iters, b, c);
        const double dt = omp_get_wtime() - t0;
        worst = std::max(worst, err);
        if (r > 0) rates.push_back(2.0 * Lanes * Chains * double(iters) * threads / dt / 1e9);
    }
    if (!(worst < 1e-9)) {
        std::fprintf(stderr, "rooflineProbe: FMA chains (%d lanes) off the closed form by %g\n",
                     Lanes, worst);
        checksOk = false;
    }
    return median(rates);
}

struct Bandwidth {
    double read, write, copy, triad; // GB/s, STREAM counting
};

Bandwidth bandwidth(const Options& o, int threads) {
    const long n = static_cast<long>(o.mib * 1048576.0 / 8);
    // Arrays without value-initialisation: the first touch below places the pages.
    std::unique_ptr<double[]> ua(new double[n]), ub(new double[n]), uc(new double[n]);
    double* a = ua.get();
    double* b = ub.get();
    double* c = uc.get();
#pragma omp parallel for num_threads(threads) schedule(static)
    for (long i = 0; i < n; ++i) {
        a[i] = 1.0;
        b[i] = 2.0;
        c[i] = 0.5;
    }
    std::vector<double> tr, tw, tc, tt;
    double sum = 0;
    const double s = 3.0;
    for (int r = 0; r <= o.reps; ++r) {
        double t0 = omp_get_wtime();
        double acc = 0;
#pragma omp parallel for simd num_threads(threads) schedule(static) reduction(+ : acc)
        for (long i = 0; i < n; ++i)
            acc += a[i]; // simd: partial sums in vector lanes (exact here: a sum of ones)
        const double dRead = omp_get_wtime() - t0;
        sum = acc;
        double two = 2.0; // b's value, hidden from the compiler (no memset)
        asm volatile("" : "+x"(two));
        t0 = omp_get_wtime();
#pragma omp parallel for num_threads(threads) schedule(static)
        for (long i = 0; i < n; ++i)
            b[i] = two;
        const double dWrite = omp_get_wtime() - t0;
        t0 = omp_get_wtime();
#pragma omp parallel for num_threads(threads) schedule(static)
        for (long i = 0; i < n; ++i)
            c[i] = a[i];
        const double dCopy = omp_get_wtime() - t0;
        t0 = omp_get_wtime();
#pragma omp parallel for num_threads(threads) schedule(static)
        for (long i = 0; i < n; ++i)
            a[i] = b[i] + s * c[i];
        const double dTriad = omp_get_wtime() - t0;
        // Undo the triad (a = b + s c = 2 + 3 a_old) so that every repetition reads the same
        // values and the read check below is exact: a_old = (a - 2)/3.
#pragma omp parallel for num_threads(threads) schedule(static)
        for (long i = 0; i < n; ++i)
            a[i] = (a[i] - 2.0) / 3.0;
        if (r > 0) {
            tr.push_back(8.0 * n / dRead / 1e9);
            tw.push_back(8.0 * n / dWrite / 1e9);
            tc.push_back(16.0 * n / dCopy / 1e9);
            tt.push_back(24.0 * n / dTriad / 1e9);
        }
        if (sum != static_cast<double>(n)) {
            std::fprintf(stderr, "rooflineProbe: read sum %.17g, expected %ld\n", sum, n);
            checksOk = false;
        }
    }
    for (long i = 0; i < n; i += 4099)
        if (c[i] != 1.0 || a[i] != 1.0 || b[i] != 2.0) {
            std::fprintf(stderr, "rooflineProbe: write/copy/triad check failed at %ld\n", i);
            checksOk = false;
            break;
        }
    return {median(tr), median(tw), median(tc), median(tt)};
}

} // namespace

int main(int argc, char* argv[]) {
    const Options o = parse(argc, argv);
    std::printf("rooflineProbe: double precision, %d-wide vectors (this build), %d FMA chains, "
                "3 arrays of %.0f MiB, median of %d repetitions\n",
                WideLanes, Chains, o.mib, o.reps);
    std::printf("%7s %10s %10s %10s %9s %9s %9s %9s %9s %9s %9s\n", "threads", "GFLOP/s", "GFLOP/s",
                "GFLOP/s", "read", "write", "write+WA", "copy", "copy+WA", "triad", "triad+WA");
    char w[16];
    std::snprintf(w, sizeof w, "%d-wide", WideLanes);
    std::printf("%7s %10s %10s %10s %9s %9s %9s %9s %9s %9s %9s\n", "", w, "4-wide", "scalar",
                "GB/s", "GB/s", "GB/s", "GB/s", "GB/s", "GB/s", "GB/s");
    std::vector<std::string> lines;
    for (int t : o.threads) {
        const double fw = flops<WideLanes>(o, t);
        const double f4 = WideLanes == 4 ? fw : flops<4>(o, t);
        const double f1 = flops<1>(o, t);
        const Bandwidth bw = bandwidth(o, t);
        const double writeWA = 2.0 * bw.write, copyWA = bw.copy * 24.0 / 16.0,
                     triadWA = bw.triad * 32.0 / 24.0;
        std::printf("%7d %10.1f %10.1f %10.1f %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f %9.1f\n", t, fw,
                    f4, f1, bw.read, bw.write, writeWA, bw.copy, copyWA, bw.triad, triadWA);
        char line[512];
        std::snprintf(line, sizeof line,
                      "ROOFLINE threads=%d lanes=%d gflops=%.2f gflops4=%.2f gflops1=%.2f "
                      "readGBs=%.2f writeGBs=%.2f writeWAGBs=%.2f copyGBs=%.2f copyWAGBs=%.2f "
                      "triadGBs=%.2f triadWAGBs=%.2f",
                      t, WideLanes, fw, f4, f1, bw.read, bw.write, writeWA, bw.copy, copyWA,
                      bw.triad, triadWA);
        lines.push_back(line);
    }
    for (const auto& l : lines)
        std::printf("%s\n", l.c_str());
    if (!checksOk) {
        std::fprintf(stderr, "rooflineProbe: a kernel's result check failed (see above)\n");
        return 1;
    }
    return 0;
}
