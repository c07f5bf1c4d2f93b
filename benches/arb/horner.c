/* One multiply-add step of a degree-17 Horner loop at 256 bits, in Arb (FLINT's ball
 * arithmetic) and in MPFR, both in place: the anchors `benches/scalar.rs` measures
 * trajverify's Ball against (docs/benchmarks.md, "Ball arithmetic against Arb").
 *
 * Build and run (Debian: apt-get install libflint-arb-dev libmpfr-dev):
 *   cc -O2 -o /tmp/horner benches/arb/horner.c -lflint-arb -lflint -lmpfr -lgmp
 *   /tmp/horner
 * Prints one line per variant: name, nanoseconds per multiply-add step (median of 15 runs
 * of 20000 evaluations each, CPU time of this process). */
#include <arb.h>
#include <mpfr.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define PREC 256
#define DEGREE 17
#define EVALS 20000
#define RUNS 15

static double cpu_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int compare(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *xs) {
    qsort(xs, RUNS, sizeof(double), compare);
    return xs[RUNS / 2];
}

/* The coefficients c_k = 1/(k + 1), rounded, with radius 2^-256 (not exact, like values a
 * computation produced), and x = 0.7 + 2^-200 ± 2^-256. */
static double arb_step(void) {
    arb_t c[DEGREE + 1], x, acc;
    for (int k = 0; k <= DEGREE; k++) {
        arb_init(c[k]);
        arb_set_ui(c[k], 1);
        arb_div_ui(c[k], c[k], k + 1, PREC);
        mag_set_ui_2exp_si(arb_radref(c[k]), 1, -256);
    }
    arb_init(x);
    arb_init(acc);
    arb_set_d(x, 0.7);
    mag_set_ui_2exp_si(arb_radref(x), 1, -256);
    double times[RUNS];
    for (int r = 0; r < RUNS; r++) {
        double start = cpu_seconds();
        for (int e = 0; e < EVALS; e++) {
            arb_set(acc, c[DEGREE]);
            for (int k = DEGREE - 1; k >= 0; k--) {
                arb_mul(acc, acc, x, PREC);
                arb_add(acc, acc, c[k], PREC);
            }
        }
        times[r] = (cpu_seconds() - start) / ((double)EVALS * DEGREE) * 1e9;
    }
    arb_printd(acc, 20);
    printf("\n");
    for (int k = 0; k <= DEGREE; k++) arb_clear(c[k]);
    arb_clear(x);
    arb_clear(acc);
    return median(times);
}

static double mpfr_step(void) {
    mpfr_t c[DEGREE + 1], x, acc;
    for (int k = 0; k <= DEGREE; k++) {
        mpfr_init2(c[k], PREC);
        mpfr_set_ui(c[k], 1, MPFR_RNDN);
        mpfr_div_ui(c[k], c[k], k + 1, MPFR_RNDN);
    }
    mpfr_init2(x, PREC);
    mpfr_init2(acc, PREC);
    mpfr_set_d(x, 0.7, MPFR_RNDN);
    double times[RUNS];
    for (int r = 0; r < RUNS; r++) {
        double start = cpu_seconds();
        for (int e = 0; e < EVALS; e++) {
            mpfr_set(acc, c[DEGREE], MPFR_RNDN);
            for (int k = DEGREE - 1; k >= 0; k--) {
                mpfr_fma(acc, acc, x, c[k], MPFR_RNDN);
            }
        }
        times[r] = (cpu_seconds() - start) / ((double)EVALS * DEGREE) * 1e9;
    }
    mpfr_printf("%.20Rg\n", acc);
    for (int k = 0; k <= DEGREE; k++) mpfr_clear(c[k]);
    mpfr_clear(x);
    mpfr_clear(acc);
    return median(times);
}

int main(void) {
    double arb = arb_step();
    double mpfr = mpfr_step();
    printf("arb_inplace_ns %.2f\n", arb);
    printf("mpfr_fma_inplace_ns %.2f\n", mpfr);
    return 0;
}
