/* The machine's rates that bound the solid level's one factorization and its
 * passes (issue 39, docs/performance.md "The physical floor"): dgemm and
 * sgemm in GFlop/s through the OpenBLAS that PETSc and MUMPS link, and the
 * memory bandwidth of a STREAM triad a = b + s c (McCalpin, "Memory
 * bandwidth and machine balance in current high performance computers",
 * IEEE TCCA Newsletter, 1995) in GB/s, counting 3 arrays x 8 bytes per
 * element as STREAM does.
 *
 *     gcc -O3 -march=native -fopenmp bench/kernel_rates.c \
 *         /usr/lib/x86_64-linux-gnu/openblas-pthread/libblas.so.3 -o /tmp/kernel_rates
 *     OPENBLAS_NUM_THREADS=2 OMP_NUM_THREADS=2 /tmp/kernel_rates [repeats]
 *
 * Each rate is the best of `repeats` (default 5): the machine's capability,
 * less the other jobs' share of it at the moment. */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

void dgemm_(const char*, const char*, const int*, const int*, const int*, const double*, const double*, const int*,
            const double*, const int*, const double*, double*, const int*);
void sgemm_(const char*, const char*, const int*, const int*, const int*, const float*, const float*, const int*,
            const float*, const int*, const float*, float*, const int*);

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Square products of order 3000: large enough for OpenBLAS's blocking to
 * reach its rate, as MUMPS's largest fronts (3,843 on case 03) do. */
enum { kOrder = 3000 };

static double gemm_rate(int single, int repeats) {
    const int n = kOrder;
    const size_t count = (size_t)n * (size_t)n;
    double best = 1e30;
    if (single) {
        float *a = malloc(count * sizeof *a), *b = malloc(count * sizeof *b), *c = malloc(count * sizeof *c);
        const float one = 1.0f, zero = 0.0f;
        for (size_t i = 0; i < count; ++i) a[i] = b[i] = (float)(i % 7) * 0.1f, c[i] = 0;
        for (int r = 0; r < repeats; ++r) {
            const double t = now();
            sgemm_("N", "N", &n, &n, &n, &one, a, &n, b, &n, &zero, c, &n);
            if (now() - t < best) best = now() - t;
        }
        free(a), free(b), free(c);
    } else {
        double *a = malloc(count * sizeof *a), *b = malloc(count * sizeof *b), *c = malloc(count * sizeof *c);
        const double one = 1.0, zero = 0.0;
        for (size_t i = 0; i < count; ++i) a[i] = b[i] = (double)(i % 7) * 0.1, c[i] = 0;
        for (int r = 0; r < repeats; ++r) {
            const double t = now();
            dgemm_("N", "N", &n, &n, &n, &one, a, &n, b, &n, &zero, c, &n);
            if (now() - t < best) best = now() - t;
        }
        free(a), free(b), free(c);
    }
    return 2.0 * n * (double)n * n / best / 1e9;
}

/* 40 M doubles per array (320 MB): far beyond the caches, as the 1.5-7 GB
 * factor is. */
static double triad_rate(int repeats) {
    const long n = 40L * 1000 * 1000;
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b), *c = malloc(n * sizeof *c);
    const double s = 3.0;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) a[i] = 0, b[i] = 1, c[i] = 2;
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
        const double t = now();
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
        if (now() - t < best) best = now() - t;
    }
    const double check = a[n / 2];
    free(a), free(b), free(c);
    if (check != 7.0) {
        fprintf(stderr, "triad: wrong result %g\n", check);
        exit(1);
    }
    return 3.0 * 8.0 * (double)n / best / 1e9;
}

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? atoi(argv[1]) : 5;
    if (repeats < 1) {
        fprintf(stderr, "usage: %s [repeats >= 1]\n", argv[0]);
        return 1;
    }
    printf("dgemm %d^2: %.1f GFlop/s\n", kOrder, gemm_rate(0, repeats));
    printf("sgemm %d^2: %.1f GFlop/s\n", kOrder, gemm_rate(1, repeats));
    printf("triad (%d threads): %.1f GB/s\n", omp_get_max_threads(), triad_rate(repeats));
    return 0;
}
