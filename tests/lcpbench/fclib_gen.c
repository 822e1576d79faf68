/* Writes the FCLib local test problems of tests/lcpbench with libfclib itself (Debian libfclib-dev):
 *   gcc fclib_gen.c -lfclib -o fclib_gen && ./fclib_gen fclib_local_3contacts.hdf5 && ./fclib_gen fclib_local_2d_csc.hdf5 csc
 * Not built by CMake: libfclib links the serial libhdf5, the suite the parallel one. */
#include <fclib.h>
#include <stdio.h>
#include <stdlib.h>
int main(int argc, char** argv) {
  const int nc = 3, d = 3, m = nc * d;
  /* W = A A^T + I, A a fixed 9x9 pattern: dense W stored as triplets (nz >= 0) */
  double A[9][9], W[9][9];
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) A[i][j] = ((i * 7 + j * 3) % 5 - 2) * 0.25;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      double s = (i == j) ? 1.0 : 0.0;
      for (int k = 0; k < m; ++k) s += A[i][k] * A[j][k];
      W[i][j] = s;
    }
  struct fclib_matrix Wm;
  Wm.m = m;
  Wm.n = m;
  Wm.nzmax = m * m;
  Wm.nz = m * m;
  Wm.p = malloc(sizeof(int) * m * m);
  Wm.i = malloc(sizeof(int) * m * m);
  Wm.x = malloc(sizeof(double) * m * m);
  int k = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      Wm.i[k] = i;
      Wm.p[k] = j;
      Wm.x[k] = W[i][j];
      ++k;
    }
  Wm.info = NULL;
  if (argc > 2) { /* CSC (nz = -1) of the same W, zeros dropped, 2-D problem of the first 6 rows */
    int mm = 6, kk = 0;
    Wm.m = mm;
    Wm.n = mm;
    Wm.nz = -1;
    for (int j = 0; j < mm; ++j) {
      Wm.p[j] = kk;
      for (int i = 0; i < mm; ++i)
        if (W[i][j] != 0.0 && (i + j) % 4 != 3) {
          Wm.i[kk] = i;
          Wm.x[kk] = W[i][j];
          ++kk;
        }
    }
    Wm.p[mm] = kk;
    Wm.nzmax = kk;
  }
  double q[9] = {-1.0, 0.2, -0.1, 0.5, 0.0, 0.3, -2.0, 0.1, 0.1};
  double mu[3] = {0.3, 0.5, 0.7};
  struct fclib_info info = {"lcpbench test", "3 contacts, dense W as triplets", "written by libfclib"};
  struct fclib_local p;
  p.W = &Wm;
  p.V = NULL;
  p.R = NULL;
  p.mu = mu;
  p.q = q;
  p.s = NULL;
  p.spacedim = argc > 2 ? 2 : d;
  p.info = &info;
  remove(argv[1]);
  if (!fclib_write_local(&p, argv[1])) {
    fprintf(stderr, "write failed\n");
    return 1;
  }
  struct fclib_local* r = fclib_read_local(argv[1]);
  printf("read back: spacedim %d, W %dx%d nz %d, q[6] %g\n", r->spacedim, r->W->m, r->W->n, r->W->nz,
         r->q[6]);
  return 0;
}
