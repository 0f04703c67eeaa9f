// Triangular solves with one or several right-hand sides on a CHOLMOD supernodal factor, with vector kernels chosen per
// processor.
#include "Numerics/SupernodalSolve.h"

#ifdef KERF_HAVE_CHOLMOD
#include "Numerics/VectorKernels.h"

#include <algorithm>
#include <cstddef>

namespace kerf
{
namespace
{
constexpr int Lanes = 8;
typedef Vector8 Lane;

KERF_INLINE Lane load(const double* p)
{
  return loadVector8(p);
}

KERF_INLINE double sum(const Lane& v)
{
  // A fixed pairwise order, whatever the vector width the compiler lowers Lane to.
  return ((v[0] + v[4]) + (v[2] + v[6])) + ((v[1] + v[5]) + (v[3] + v[7]));
}

// v[j] for the supernode's columns j (nsc of them) from L v = v on its diagonal block, and the
// rows below (v[nsc..nsr), the values of the rows they update) minus the block's contribution.
// L is the supernode's column-major block (nsr rows). Four columns at a time: their small
// triangle first, then one pass over the rows below.
KERF_VECTOR_CLONES
void forwardBlock(const double* __restrict L, int nsr, int nsc, double* __restrict v)
{
  const std::size_t ld = static_cast<std::size_t>(nsr);
  int j = 0;
  for (; j + 4 <= nsc; j += 4)
  {
    const double* c0 = L + j * ld;
    const double* c1 = c0 + ld;
    const double* c2 = c1 + ld;
    const double* c3 = c2 + ld;
    const double v0 = v[j] / c0[j];
    const double v1 = (v[j + 1] - c0[j + 1] * v0) / c1[j + 1];
    const double v2 = (v[j + 2] - c0[j + 2] * v0 - c1[j + 2] * v1) / c2[j + 2];
    const double v3 = (v[j + 3] - c0[j + 3] * v0 - c1[j + 3] * v1 - c2[j + 3] * v2) / c3[j + 3];
    v[j] = v0;
    v[j + 1] = v1;
    v[j + 2] = v2;
    v[j + 3] = v3;
    for (int i = j + 4; i < nsr; ++i)
    {
      v[i] -= ((c0[i] * v0 + c1[i] * v1) + c2[i] * v2) + c3[i] * v3;
    }
  }
  for (; j < nsc; ++j)
  {
    const double* c = L + j * ld;
    const double vj = v[j] / c[j];
    v[j] = vj;
    for (int i = j + 1; i < nsr; ++i)
    {
      v[i] -= c[i] * vj;
    }
  }
}

// v[j] for the supernode's columns from L^T v = v, given the final values of the rows below
// (v[nsc..nsr)). Four columns at a time, from the last: their dot products with the rows below
// them in one pass, then their small triangle.
KERF_VECTOR_CLONES
void backwardBlock(const double* __restrict L, int nsr, int nsc, double* __restrict v)
{
  const std::size_t ld = static_cast<std::size_t>(nsr);
  int j = nsc;
  for (; j >= 4; j -= 4)
  {
    const int j0 = j - 4;
    const double* c0 = L + j0 * ld;
    const double* c1 = c0 + ld;
    const double* c2 = c1 + ld;
    const double* c3 = c2 + ld;
    Lane a0 = {}, a1 = {}, a2 = {}, a3 = {};
    int i = j;
    for (; i + Lanes <= nsr; i += Lanes)
    {
      const Lane x = load(v + i);
      a0 += load(c0 + i) * x;
      a1 += load(c1 + i) * x;
      a2 += load(c2 + i) * x;
      a3 += load(c3 + i) * x;
    }
    double s0 = sum(a0), s1 = sum(a1), s2 = sum(a2), s3 = sum(a3);
    for (; i < nsr; ++i)
    {
      s0 += c0[i] * v[i];
      s1 += c1[i] * v[i];
      s2 += c2[i] * v[i];
      s3 += c3[i] * v[i];
    }
    const double v3 = (v[j0 + 3] - s3) / c3[j0 + 3];
    const double v2 = (v[j0 + 2] - s2 - c2[j0 + 3] * v3) / c2[j0 + 2];
    const double v1 = (v[j0 + 1] - s1 - c1[j0 + 2] * v2 - c1[j0 + 3] * v3) / c1[j0 + 1];
    const double v0 = (v[j0] - s0 - c0[j0 + 1] * v1 - c0[j0 + 2] * v2 - c0[j0 + 3] * v3) / c0[j0];
    v[j0] = v0;
    v[j0 + 1] = v1;
    v[j0 + 2] = v2;
    v[j0 + 3] = v3;
  }
  for (--j; j >= 0; --j)
  {
    const double* c = L + j * ld;
    Lane a = {};
    int i = j + 1;
    for (; i + Lanes <= nsr; i += Lanes)
    {
      a += load(c + i) * load(v + i);
    }
    double s = sum(a);
    for (; i < nsr; ++i)
    {
      s += c[i] * v[i];
    }
    v[j] = (v[j] - s) / c[j];
  }
}

// The complex kernels: values interleaved (real, imaginary), four complex numbers per Lane. For a
// column value w = (wr, wi) and column entries a: a w = a * (wr, wr) + swap(a) * (-wi, wi).
typedef long LaneIndex __attribute__((vector_size(8 * sizeof(long))));

KERF_INLINE Lane swapPairs(const Lane& a)
{
#if defined(__clang__)
  return __builtin_shufflevector(a, a, 1, 0, 3, 2, 5, 4, 7, 6);
#else
  return __builtin_shuffle(a, LaneIndex{ 1, 0, 3, 2, 5, 4, 7, 6 });
#endif
}

KERF_INLINE Lane realLanes(double wr)
{
  return Lane{ wr, wr, wr, wr, wr, wr, wr, wr };
}

KERF_INLINE Lane signedImaginaryLanes(double wi)
{
  return Lane{ -wi, wi, -wi, wi, -wi, wi, -wi, wi };
}

// forwardBlock for a complex factor (L L^H, real diagonal): two columns at a time.
KERF_VECTOR_CLONES
void forwardBlockComplex(const double* __restrict L, int nsr, int nsc, double* __restrict v)
{
  const std::size_t ld = 2 * static_cast<std::size_t>(nsr);
  int j = 0;
  for (; j + 2 <= nsc; j += 2)
  {
    const double* c0 = L + j * ld;
    const double* c1 = c0 + ld;
    const double d0 = c0[2 * j];
    const double d1 = c1[2 * (j + 1)];
    const double w0r = v[2 * j] / d0;
    const double w0i = v[2 * j + 1] / d0;
    // v[j + 1] -= L[j + 1, j] w0
    const double ar = c0[2 * (j + 1)], ai = c0[2 * (j + 1) + 1];
    const double w1r = (v[2 * (j + 1)] - (ar * w0r - ai * w0i)) / d1;
    const double w1i = (v[2 * (j + 1) + 1] - (ar * w0i + ai * w0r)) / d1;
    v[2 * j] = w0r;
    v[2 * j + 1] = w0i;
    v[2 * (j + 1)] = w1r;
    v[2 * (j + 1) + 1] = w1i;
    const Lane r0 = realLanes(w0r), i0 = signedImaginaryLanes(w0i);
    const Lane r1 = realLanes(w1r), i1 = signedImaginaryLanes(w1i);
    int i = 2 * (j + 2);
    const int end = 2 * nsr;
    for (; i + Lanes <= end; i += Lanes)
    {
      const Lane a0 = load(c0 + i);
      const Lane a1 = load(c1 + i);
      const Lane update = (a0 * r0 + swapPairs(a0) * i0) + (a1 * r1 + swapPairs(a1) * i1);
      storeVector8(v + i, load(v + i) - update);
    }
    for (; i < end; i += 2)
    {
      const double re = (c0[i] * w0r - c0[i + 1] * w0i) + (c1[i] * w1r - c1[i + 1] * w1i);
      const double im = (c0[i + 1] * w0r + c0[i] * w0i) + (c1[i + 1] * w1r + c1[i] * w1i);
      v[i] -= re;
      v[i + 1] -= im;
    }
  }
  for (; j < nsc; ++j)
  {
    const double* c = L + j * ld;
    const double d = c[2 * j];
    const double wr = v[2 * j] / d;
    const double wi = v[2 * j + 1] / d;
    v[2 * j] = wr;
    v[2 * j + 1] = wi;
    for (int i = 2 * (j + 1); i < 2 * nsr; i += 2)
    {
      v[i] -= c[i] * wr - c[i + 1] * wi;
      v[i + 1] -= c[i + 1] * wr + c[i] * wi;
    }
  }
}

// sum over the rows i in [from, nsr) of conj(c[i]) v[i], c and v interleaved complex.
KERF_INLINE void conjugateDot(
  const double* __restrict c, const double* __restrict v, int from, int nsr, double& re, double& im)
{
  Lane p = {}, q = {};
  int i = 2 * from;
  const int end = 2 * nsr;
  for (; i + Lanes <= end; i += Lanes)
  {
    const Lane a = load(c + i);
    const Lane x = load(v + i);
    p += a * x;            // (ar xr, ai xi): their sum is the real part
    q += swapPairs(a) * x; // (ai xr, ar xi): ar xi - ai xr is the imaginary part
  }
  re = sum(p);
  im = ((q[1] - q[0]) + (q[5] - q[4])) + ((q[3] - q[2]) + (q[7] - q[6]));
  for (; i < end; i += 2)
  {
    re += c[i] * v[i] + c[i + 1] * v[i + 1];
    im += c[i] * v[i + 1] - c[i + 1] * v[i];
  }
}

// backwardBlock for a complex factor: L^H v = v, one column at a time from the last.
KERF_VECTOR_CLONES
void backwardBlockComplex(const double* __restrict L, int nsr, int nsc, double* __restrict v)
{
  const std::size_t ld = 2 * static_cast<std::size_t>(nsr);
  for (int j = nsc - 1; j >= 0; --j)
  {
    const double* c = L + j * ld;
    double re = 0.0, im = 0.0;
    conjugateDot(c, v, j + 1, nsr, re, im);
    const double d = c[2 * j];
    v[2 * j] = (v[2 * j] - re) / d;
    v[2 * j + 1] = (v[2 * j + 1] - im) / d;
  }
}

// A supernode's rows: its own columns first, then the rows below its diagonal block.
struct Block
{
  int first; // the first column
  int nsc;   // columns
  int nsr;   // rows
  const int* rows;
};

struct Supernodes
{
  const int* super;
  const int* pi;
  const int* px;
  const int* rows;
  const double* values;
  int count;

  explicit Supernodes(const cholmod_factor& factor)
    : super(static_cast<const int*>(factor.super))
    , pi(static_cast<const int*>(factor.pi))
    , px(static_cast<const int*>(factor.px))
    , rows(static_cast<const int*>(factor.s))
    , values(static_cast<const double*>(factor.x))
    , count(static_cast<int>(factor.nsuper))
  {
  }
  /// Copies the values of supernode `node`'s rows from y into v, in its row order; Width doubles
  /// per value (1 real, 2 complex).
  template <int Width = 1>
  Block gather(int node, const double* y, double* v) const
  {
    const Block b{ this->super[node], this->super[node + 1] - this->super[node], this->pi[node + 1] - this->pi[node],
      this->rows + this->pi[node] };
    std::copy(y + Width * b.first, y + Width * (b.first + b.nsc), v);
    for (int i = b.nsc; i < b.nsr; ++i)
    {
      std::copy(y + Width * b.rows[i], y + Width * (b.rows[i] + 1), v + Width * i);
    }
    return b;
  }
  /// Writes v back to the rows below supernode b's columns (the forward sweep's updates).
  template <int Width = 1>
  static void scatterBelow(const Block& b, const double* v, double* y)
  {
    for (int i = b.nsc; i < b.nsr; ++i)
    {
      std::copy(v + Width * i, v + Width * (i + 1), y + Width * b.rows[i]);
    }
  }
  int largest() const
  {
    int most = 0;
    for (int s = 0; s < this->count; ++s)
    {
      most = std::max(most, this->pi[s + 1] - this->pi[s]);
    }
    return most;
  }
};
} // namespace

bool SupernodalSolve::supports(const cholmod_factor& factor)
{
  return factor.is_super && factor.xtype == CHOLMOD_REAL && factor.dtype == CHOLMOD_DOUBLE &&
    factor.itype == CHOLMOD_INT;
}

namespace
{
// L^-1 (Forward) or L^-T on `columns` vectors of n values (column c at y + c n, permuted row
// order), supernode by supernode (from the last for L^-T), each supernode applied to every column
// while its block is in the cache.
template <bool Forward>
void sweep(const Supernodes& s, std::size_t n, double* y, int columns, std::vector<double>& workspace)
{
  const std::size_t width = static_cast<std::size_t>(s.largest());
  workspace.resize(width * static_cast<std::size_t>(std::max(columns, 1)));
  for (int step = 0; step < s.count; ++step)
  {
    const int node = Forward ? step : s.count - 1 - step;
    for (int c = 0; c < columns; ++c)
    {
      double* v = workspace.data() + c * width;
      double* yc = y + c * n;
      const Block block = s.gather(node, yc, v);
      if (Forward)
      {
        forwardBlock(s.values + s.px[node], block.nsr, block.nsc, v);
      }
      else
      {
        backwardBlock(s.values + s.px[node], block.nsr, block.nsc, v);
      }
      std::copy(v, v + block.nsc, yc + block.first);
      if (Forward)
      {
        Supernodes::scatterBelow(block, v, yc);
      }
    }
  }
}
} // namespace

void SupernodalSolve::forward(const cholmod_factor& factor, double* y, std::vector<double>& workspace)
{
  sweep<true>(Supernodes(factor), factor.n, y, 1, workspace);
}

void SupernodalSolve::backward(const cholmod_factor& factor, double* y, std::vector<double>& workspace)
{
  sweep<false>(Supernodes(factor), factor.n, y, 1, workspace);
}

void SupernodalSolve::solve(const cholmod_factor& factor, const double* b, double* x, std::vector<double>& workspace)
{
  solveColumns(factor, b, x, 1, workspace);
}

void SupernodalSolve::solveColumns(
  const cholmod_factor& factor, const double* b, double* x, int columns, std::vector<double>& workspace)
{
  const std::size_t n = factor.n;
  const int* perm = static_cast<const int*>(factor.Perm);
  const Supernodes s(factor);
  std::vector<double> y(n * static_cast<std::size_t>(std::max(columns, 0)));
  for (int c = 0; c < columns; ++c)
  {
    for (std::size_t k = 0; k < n; ++k)
    {
      y[c * n + k] = b[c * n + static_cast<std::size_t>(perm ? perm[k] : static_cast<int>(k))];
    }
  }
  sweep<true>(s, n, y.data(), columns, workspace);
  sweep<false>(s, n, y.data(), columns, workspace);
  for (int c = 0; c < columns; ++c)
  {
    for (std::size_t k = 0; k < n; ++k)
    {
      x[c * n + static_cast<std::size_t>(perm ? perm[k] : static_cast<int>(k))] = y[c * n + k] + 0.0;
    }
  }
}

bool SupernodalSolve::supportsComplex(const cholmod_factor& factor)
{
  return factor.is_super && factor.xtype == CHOLMOD_COMPLEX && factor.dtype == CHOLMOD_DOUBLE &&
    factor.itype == CHOLMOD_INT;
}

void SupernodalSolve::solveComplex(
  const cholmod_factor& factor, const std::complex<double>* b, std::complex<double>* x, std::vector<double>& workspace)
{
  const std::size_t n = factor.n;
  const int* perm = static_cast<const int*>(factor.Perm);
  const Supernodes s(factor);
  workspace.resize(2 * static_cast<std::size_t>(s.largest()));
  double* v = workspace.data();
  std::vector<double> y(2 * n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::complex<double>& value = b[perm ? perm[k] : static_cast<int>(k)];
    y[2 * k] = value.real();
    y[2 * k + 1] = value.imag();
  }
  // The values of supernode s start at complex entry px[s].
  for (int node = 0; node < s.count; ++node)
  {
    const Block block = s.gather<2>(node, y.data(), v);
    forwardBlockComplex(s.values + 2 * static_cast<std::size_t>(s.px[node]), block.nsr, block.nsc, v);
    std::copy(v, v + 2 * block.nsc, y.begin() + 2 * block.first);
    Supernodes::scatterBelow<2>(block, v, y.data());
  }
  for (int node = s.count - 1; node >= 0; --node)
  {
    const Block block = s.gather<2>(node, y.data(), v);
    backwardBlockComplex(s.values + 2 * static_cast<std::size_t>(s.px[node]), block.nsr, block.nsc, v);
    std::copy(v, v + 2 * block.nsc, y.begin() + 2 * block.first);
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    x[perm ? perm[k] : static_cast<int>(k)] = std::complex<double>(y[2 * k] + 0.0, y[2 * k + 1] + 0.0);
  }
}

} // namespace kerf
#endif
