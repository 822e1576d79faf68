// Roe average of two states and the right/left eigenvectors of the 1D Euler flux Jacobian at that state, used
// for characteristic-wise reconstruction. Reference: Roe, J. Comput. Phys. 43 (1981) 357; Toro (2009) eqs.
// (3.23), (11.60)-(11.63); left eigenvectors as in Shu, ICASE report 97-65 (1997), sec. 2.3.
#pragma once

#include "euler/gas.hpp"

namespace suite::euler {

struct Eigensystem {
  Mat3 R; // columns: right eigenvectors for u - c, u, u + c
  Mat3 L; // rows: left eigenvectors, L R = I
  double u, c;
};

// Roe-averaged eigensystem between conserved states qa and qb.
Eigensystem roeEigensystem(const Vec3& qa, const Vec3& qb, double gamma);

inline Vec3 mul(const Mat3& M, const Vec3& v) {
  return {M[0] * v[0] + M[1] * v[1] + M[2] * v[2], M[3] * v[0] + M[4] * v[1] + M[5] * v[2],
          M[6] * v[0] + M[7] * v[1] + M[8] * v[2]};
}

} // namespace suite::euler
