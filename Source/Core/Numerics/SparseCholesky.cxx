// CHOLMOD-backed sparse Cholesky with sparse multi-column forward solves for low-rank corrections.
#include "Numerics/SparseCholesky.h"

#include "Error.h"
#include "Numerics/SerialOpenMP.h"
#include "Numerics/SupernodalFactorization.h"
#include "Numerics/SupernodalSolve.h"
#include "Numerics/VectorKernels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#ifdef KERF_HAVE_CHOLMOD
#include <cholmod.h>
#else
#include <Eigen/SparseCholesky>
#endif

namespace kerf
{
namespace
{
/// Throws when a low-rank term has a NaN or infinite entry (compressed or not).
void checkFinite(const Eigen::SparseMatrix<double>& U)
{
  for (Eigen::Index c = 0; c < U.outerSize(); ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(U, c); it; ++it)
    {
      if (!std::isfinite(it.value()))
      {
        throw Error("the low-rank term has NaN or infinite entries");
      }
    }
  }
}
} // namespace

#ifdef KERF_HAVE_CHOLMOD

namespace
{
cholmod_dense cholmodView(const double* values, std::size_t n, std::size_t columns = 1)
{
  cholmod_dense d{};
  d.nrow = n;
  d.ncol = columns;
  d.nzmax = n * columns;
  d.d = n;
  d.x = const_cast<double*>(values);
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

// A pattern-only cholmod_sparse column over `rows` (no copy).
cholmod_sparse cholmodPattern(std::size_t n, std::vector<int>& rows, int (&pointers)[2])
{
  pointers[0] = 0;
  pointers[1] = static_cast<int>(rows.size());
  cholmod_sparse s{};
  s.nrow = n;
  s.ncol = 1;
  s.nzmax = std::max<std::size_t>(1, rows.size());
  s.p = pointers;
  s.i = rows.data();
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_PATTERN;
  s.dtype = CHOLMOD_DOUBLE;
  s.packed = 1;
  return s;
}

// Dense kernels of the supernodal forward solve, on row-major blocks of right-hand sides padded
// to a multiple of ColumnChunk columns. Every right-hand side sees the same arithmetic in the
// same order whatever the others are, so a column's values do not depend on which columns are
// solved with it. Compiled for AVX-512, AVX2 with FMA and the x86-64 baseline; the processor
// picks one when the library loads (the factor's own BLAS kernels are chosen per processor too).
constexpr int ColumnChunk = 8;
constexpr int TileRows = 8;
typedef Vector8 Chunk;
static_assert(sizeof(Chunk) == ColumnChunk * sizeof(double), "a chunk is one Vector8");

KERF_INLINE Chunk loadChunk(const double* p)
{
  return loadVector8(p);
}

KERF_INLINE void storeChunk(double* p, const Chunk& v)
{
  storeVector8(p, v);
}

// Y_i -= sum_{t < depth} L(i, t) y[t] for rows [begin, end) of a block whose columns start at
// `block` (leading dimension ld), on one chunk of columns; row i's values start at target(i).
template <int Depth, typename Target>
KERF_INLINE void subtractBlock(
  const double* block, std::size_t ld, int depth, const Chunk* y, int begin, int end, Target target)
{
  for (int i = begin; i < end; ++i)
  {
    Chunk acc = block[i] * y[0];
    for (int t = 1; t < (Depth > 0 ? Depth : depth); ++t)
    {
      acc += block[i + t * ld] * y[t];
    }
    double* row = target(i);
    storeChunk(row, loadChunk(row) - acc);
  }
}

// One supernode of the forward solve L Y = B on the listed chunks of columns (their first
// columns): the rows of its diagonal block (Ys, `width` values per row) are solved in place and
// its contribution is subtracted from the rows below (targets[i - columns] for block row i).
// L is the supernode's column-major block with leading dimension ld. The columns go in blocks of
// TileRows: each block's solved rows stay in registers while its columns of L stream by in
// memory order, and every row below subtracts one block's sum at a time.
KERF_VECTOR_CLONES
void forwardSupernode(const double* L, int ld, int columns, int rows, double* Ys, double* const* targets, int width,
  const int* chunks, int chunkCount)
{
  const std::size_t stride = static_cast<std::size_t>(ld);
  for (int t0 = 0; t0 < columns; t0 += TileRows)
  {
    const int depth = std::min(TileRows, columns - t0);
    const double* block = L + t0 * stride;
    for (int chunk = 0; chunk < chunkCount; ++chunk)
    {
      const int c0 = chunks[chunk];
      // The block's own rows: a small triangular solve.
      Chunk y[TileRows];
      for (int r = 0; r < depth; ++r)
      {
        double* row = Ys + static_cast<std::size_t>(t0 + r) * width + c0;
        Chunk v = loadChunk(row);
        for (int q = 0; q < r; ++q)
        {
          v -= block[t0 + r + q * stride] * y[q];
        }
        y[r] = v / block[t0 + r + r * stride];
        storeChunk(row, y[r]);
      }
      auto inBlock = [Ys, width, c0](int i) { return Ys + static_cast<std::size_t>(i) * width + c0; };
      auto below = [targets, columns, c0](int i) { return targets[i - columns] + c0; };
      if (depth == TileRows)
      {
        subtractBlock<TileRows>(block, stride, depth, y, t0 + depth, columns, inBlock);
        subtractBlock<TileRows>(block, stride, depth, y, columns, rows, below);
      }
      else
      {
        subtractBlock<0>(block, stride, depth, y, t0 + depth, columns, inBlock);
        subtractBlock<0>(block, stride, depth, y, columns, rows, below);
      }
    }
  }
}

// Resets workspace entries to -1 when it goes out of scope, exceptions included.
class Marks
{
public:
  Marks(std::vector<int>& workspace, const std::vector<int>& marked)
    : Workspace(workspace)
    , Marked(marked)
  {
  }
  ~Marks()
  {
    for (int i : this->Marked)
    {
      this->Workspace[i] = -1;
    }
  }
  Marks(const Marks&) = delete;
  Marks& operator=(const Marks&) = delete;

private:
  std::vector<int>& Workspace;
  const std::vector<int>& Marked;
};

int paddedWidth(int k)
{
  return std::max(ColumnChunk, (k + ColumnChunk - 1) / ColumnChunk * ColumnChunk);
}

using ColumnKey = std::vector<std::pair<int, double>>; // a column's entries

/// U's distinct columns, sorted by their entries, and where the sweep computes each: the ones
/// the last prepare() computed keep their values and come first; the new ones follow from a
/// whole chunk on.
struct ColumnPlan
{
  std::vector<ColumnKey> keys;  // the distinct columns
  std::vector<int> distinct;    // U's column -> its distinct column
  std::vector<int> kept, fresh; // distinct columns computed before / not
  std::vector<int> source;      // each kept column's distinct column in the last call
  std::vector<int> slot;        // distinct column -> its column in the sweep's rows
  int freshBase = 0;
  int width = 0; // values per row in the sweep (a multiple of ColumnChunk)
};

// C = A^T A (lower triangle) for a row-major A (k x n): BLAS's syrk on the column-major A^T.
extern "C" void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
  const double* a, const int* lda, const double* beta, double* c, const int* ldc);
} // namespace

/// Y = L^-1 P U on its reach, for apply() and for the next prepare().
struct SparseCholesky::LowRankFactor
{
  /// Rows of y on which only a range of its columns can be nonzero.
  struct Block
  {
    int firstRow = 0, rowCount = 0; ///< rows [firstRow, firstRow + rowCount) of y
    int first = 0, last = 0;        ///< columns [first, last] of y
  };
  std::vector<ColumnKey> keys;  ///< U's distinct columns, sorted
  std::vector<int> distinct;    ///< U's column -> its distinct column
  std::vector<int> column;      ///< distinct column -> its column in y
  std::vector<int> supernodes;  ///< the reach, ascending
  std::vector<int> firstRow;    ///< each reach supernode's first row in y
  std::vector<int> rows;        ///< the permuted row of each row of y
  std::vector<Block> blocks;    ///< y's rows in order, grouped by the range of columns nonzero on them
  std::vector<double> y;        ///< row-major, one value per distinct column, in the order of `column`
  std::uint64_t generation = 0; ///< the factorization it belongs to
  int count() const { return static_cast<int>(this->keys.size()); }
};

struct SparseCholesky::Implementation
{
  cholmod_common common;
  cholmod_factor* factor = nullptr; // supernodal L L^T after factor()
  SupernodalRoute route = SupernodalRoute::Automatic;
  std::vector<int> inversePermutation; // original row -> permuted row
  std::vector<int> supernodeOf;        // permuted row -> its supernode
  std::vector<int> superParent;        // supernodal elimination tree
  mutable std::vector<int> offset;     // workspace: supernode -> first row in a reach, or -1
  mutable std::vector<int> lastOffset; // workspace: supernode -> first row in last's reach, or -1
  // The last supernodal sweep's Y: a U that keeps some of its columns (a refined cut) only
  // solves for the new ones. Each column's values do not depend on the others solved with it, so
  // reuse gives the same bits as solving afresh.
  mutable std::shared_ptr<const LowRankFactor> last;
  std::uint64_t generation = 0; // counts factorizations, so a LowRank knows which it belongs to
  // A simplicial copy of the factor for cholmod_solve2 with sparse right-hand sides (made on
  // first use), and cholmod_solve2's reusable workspace.
  mutable cholmod_factor* simplicial = nullptr;
  mutable cholmod_dense* solveX = nullptr;
  mutable cholmod_dense* solveY = nullptr;
  mutable cholmod_dense* solveE = nullptr;
  mutable cholmod_sparse* solveXset = nullptr;
  mutable std::vector<double> solveWork; // SupernodalSolve's workspace

  Implementation()
  {
    startCholmod(&this->common);
    this->common.print = 0;
    this->common.error_handler = nullptr;
  }
  ~Implementation()
  {
    this->freeFactors();
    cholmod_free_dense(&this->solveX, &this->common);
    cholmod_free_dense(&this->solveY, &this->common);
    cholmod_free_dense(&this->solveE, &this->common);
    cholmod_free_sparse(&this->solveXset, &this->common);
    cholmod_finish(&this->common);
  }
  Implementation(const Implementation&) = delete;
  Implementation& operator=(const Implementation&) = delete;

  void freeFactors()
  {
    if (this->factor)
    {
      cholmod_free_factor(&this->factor, &this->common);
    }
    if (this->simplicial)
    {
      cholmod_free_factor(&this->simplicial, &this->common);
    }
  }
  // CHOLMOD's calls take a non-const common for its statistics and workspace; the const methods
  // share it (one thread at a time).
  cholmod_common* mutableCommon() const { return const_cast<cholmod_common*>(&this->common); }
  const cholmod_factor& factorFor(Eigen::Index rows) const;

  const int* super() const { return static_cast<const int*>(this->factor->super); }
  const int* pi() const { return static_cast<const int*>(this->factor->pi); }
  const int* px() const { return static_cast<const int*>(this->factor->px); }
  const int* rows() const { return static_cast<const int*>(this->factor->s); }
  const double* values() const { return static_cast<const double*>(this->factor->x); }

  /// The supernodes on the paths from the given ones to the root, ascending (a topological
  /// order), into `reach`; `offset` then gives each one's first row among the reach's rows, and
  /// `rowCount` is the number of rows. A supernode is in `reach` before it is marked, so a Marks
  /// guard over `reach` always restores the workspace.
  void reachOf(const std::vector<int>& starts, std::vector<int>& reach, std::size_t& rowCount) const
  {
    for (int start : starts)
    {
      for (int s = start; s >= 0 && this->offset[s] < 0; s = this->superParent[s])
      {
        reach.push_back(s);
        this->offset[s] = 0;
      }
    }
    std::sort(reach.begin(), reach.end());
    rowCount = 0;
    for (int s : reach)
    {
      this->offset[s] = static_cast<int>(rowCount);
      rowCount += static_cast<std::size_t>(this->super()[s + 1] - this->super()[s]);
    }
  }
  /// The position of permuted row j among the reach's rows.
  int position(int j) const
  {
    const int s = this->supernodeOf[j];
    return this->offset[s] + j - this->super()[s];
  }
  /// The permuted rows of a reach, in order.
  std::vector<int> rowsOf(const std::vector<int>& reach, std::size_t rowCount) const
  {
    std::vector<int> out;
    out.reserve(rowCount);
    for (int s : reach)
    {
      for (int j = this->super()[s]; j < this->super()[s + 1]; ++j)
      {
        out.push_back(j);
      }
    }
    return out;
  }

  // The steps of prepare(), in order; `work` holds the sweep's rows (plan.width values each).
  static ColumnPlan planColumns(const Eigen::SparseMatrix<double>& U, const LowRankFactor* previous);
  void reachOfColumns(const ColumnPlan& plan, LowRankFactor& out) const;
  void blocksOfColumns(const ColumnPlan& plan, LowRankFactor& out) const;
  void copyKeptColumns(
    const ColumnPlan& plan, const LowRankFactor* previous, const LowRankFactor& out, std::vector<double>& work) const;
  void scatterFreshColumns(const ColumnPlan& plan, std::vector<double>& work) const;
  void sweepFreshColumns(const ColumnPlan& plan, const LowRankFactor& out, std::vector<double>& work) const;
  void solveFreshColumnsOneByOne(const ColumnPlan& plan, std::vector<double>& work) const;
  void solveFreshColumnsTogether(const ColumnPlan& plan, std::vector<double>& work) const;
  static void keepDistinctColumns(const ColumnPlan& plan, const std::vector<double>& work, LowRankFactor& out);
  static Eigen::MatrixXd gramOf(const LowRankFactor& out);
  cholmod_factor* simplicialFactor() const;
};

SparseCholesky::SparseCholesky()
  : Impl(new Implementation)
{
}

SparseCholesky::~SparseCholesky() = default;

std::string SparseCholesky::backend()
{
  return "CHOLMOD";
}

std::size_t SparseCholesky::factorNonZeros() const
{
  const Implementation& m = *this->Impl;
  return m.factor ? static_cast<std::size_t>(m.factor->xsize) : 0;
}

void SparseCholesky::setSupernodalRoute(SupernodalRoute route)
{
  this->Impl->route = route;
}

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A, Ordering ordering)
{
  return this->factorOrdered(A, ordering, nullptr);
}

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A, const std::vector<int>& permutation)
{
  if (permutation.size() != static_cast<std::size_t>(A.rows()))
  {
    throw Error("a fill-reducing permutation needs one entry per row (" + std::to_string(A.rows()) + ")");
  }
  std::vector<char> seen(permutation.size(), 0);
  for (int p : permutation)
  {
    if (p < 0 || p >= static_cast<int>(permutation.size()) || seen[p])
    {
      throw Error("the fill-reducing permutation is not a permutation of the rows");
    }
    seen[p] = 1;
  }
  return this->factorOrdered(A, Ordering::AMD, &permutation);
}

std::vector<int> SparseCholesky::permutation() const
{
  const Implementation& m = *this->Impl;
  if (!m.factor)
  {
    return {};
  }
  const int* perm = static_cast<const int*>(m.factor->Perm);
  return std::vector<int>(perm, perm + m.factor->n);
}

bool SparseCholesky::factorOrdered(
  const Eigen::SparseMatrix<double>& A, Ordering ordering, const std::vector<int>* given)
{
  Implementation& m = *this->Impl;
  m.freeFactors();
  m.last.reset();
  ++m.generation;
  Eigen::SparseMatrix<double> compressed;
  if (!A.isCompressed())
  {
    compressed = A;
    compressed.makeCompressed();
  }
  cholmod_sparse s = cholmodView(A.isCompressed() ? A : compressed, -1);
  m.common.nmethods = 1;
  m.common.method[0].ordering = given ? CHOLMOD_GIVEN : ordering == Ordering::AMD ? CHOLMOD_AMD : CHOLMOD_METIS;
  m.common.supernodal = CHOLMOD_SUPERNODAL;
  const CholmodAllocatorScope allocator; // the analysis's workspace too
  m.factor = given ? cholmod_analyze_p(&s, const_cast<int*>(given->data()), nullptr, 0, &m.common)
                   : cholmod_analyze(&s, &m.common);
  if (!m.factor)
  {
    return false;
  }
  bool factored = false;
  {
    const SerialOpenMP serial;
    factored = factorizeSupernodal(&s, m.factor, &m.common, m.route);
  }
  if (!factored || m.common.status != CHOLMOD_OK || m.factor->minor < m.factor->n || !m.factor->is_super)
  {
    cholmod_free_factor(&m.factor, &m.common);
    return false;
  }
  const int n = static_cast<int>(m.factor->n);
  const int supernodes = static_cast<int>(m.factor->nsuper);
  const int* perm = static_cast<const int*>(m.factor->Perm);
  m.inversePermutation.assign(n, 0);
  for (int j = 0; j < n; ++j)
  {
    m.inversePermutation[perm[j]] = j;
  }
  m.supernodeOf.assign(n, 0);
  for (int s = 0; s < supernodes; ++s)
  {
    for (int j = m.super()[s]; j < m.super()[s + 1]; ++j)
    {
      m.supernodeOf[j] = s;
    }
  }
  // The parent of a supernode holds its smallest row below the diagonal block.
  m.superParent.assign(supernodes, -1);
  for (int s = 0; s < supernodes; ++s)
  {
    const int columns = m.super()[s + 1] - m.super()[s];
    int smallest = n;
    for (int e = m.pi()[s] + columns; e < m.pi()[s + 1]; ++e)
    {
      smallest = std::min(smallest, m.rows()[e]);
    }
    m.superParent[s] = smallest < n ? m.supernodeOf[smallest] : -1;
  }
  m.offset.assign(supernodes, -1);
  m.lastOffset.assign(supernodes, -1);
  return true;
}

// The factor a right-hand side of `rows` rows is solved with; throws kerf::Error without one or
// for another number of rows.
const cholmod_factor& SparseCholesky::Implementation::factorFor(Eigen::Index rows) const
{
  if (!this->factor)
  {
    throw Error("no factorization to solve with");
  }
  if (rows != static_cast<Eigen::Index>(this->factor->n))
  {
    throw Error("the right-hand side does not match the factored matrix");
  }
  return *this->factor;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const
{
  const cholmod_factor& factor = this->Impl->factorFor(b.size());
  Eigen::VectorXd x(b.size());
  SupernodalSolve::solve(factor, b.data(), x.data(), this->Impl->solveWork);
  return x;
}

Eigen::MatrixXd SparseCholesky::solveBlock(const Eigen::MatrixXd& b) const
{
  const cholmod_factor& factor = this->Impl->factorFor(b.rows());
  Eigen::MatrixXd x(b.rows(), b.cols());
  SupernodalSolve::solveColumns(factor, b.data(), x.data(), static_cast<int>(b.cols()), this->Impl->solveWork);
  return x;
}

Eigen::MatrixXd SparseCholesky::solveColumns(const Eigen::MatrixXd& b) const
{
  const Implementation& m = *this->Impl;
  m.factorFor(b.rows());
  cholmod_dense rhs = cholmodView(b.data(), static_cast<std::size_t>(b.rows()), static_cast<std::size_t>(b.cols()));
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, m.factor, &rhs, m.mutableCommon());
  if (!x)
  {
    throw Error("the sparse solve failed");
  }
  Eigen::MatrixXd result = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), b.rows(), b.cols());
  cholmod_free_dense(&x, m.mutableCommon());
  return result;
}

ColumnPlan SparseCholesky::Implementation::planColumns(
  const Eigen::SparseMatrix<double>& U, const LowRankFactor* previous)
{
  const int k = static_cast<int>(U.cols());
  std::vector<ColumnKey> keys(k);
  for (int c = 0; c < k; ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(U, c); it; ++it)
    {
      keys[c].emplace_back(static_cast<int>(it.row()), it.value());
    }
  }
  ColumnPlan plan;
  plan.keys = keys;
  std::sort(plan.keys.begin(), plan.keys.end());
  plan.keys.erase(std::unique(plan.keys.begin(), plan.keys.end()), plan.keys.end());
  plan.distinct.resize(k);
  for (int c = 0; c < k; ++c)
  {
    plan.distinct[c] =
      static_cast<int>(std::lower_bound(plan.keys.begin(), plan.keys.end(), keys[c]) - plan.keys.begin());
  }
  for (int d = 0; d < static_cast<int>(plan.keys.size()); ++d)
  {
    const auto found = previous ? std::lower_bound(previous->keys.begin(), previous->keys.end(), plan.keys[d])
                                : std::vector<ColumnKey>::const_iterator();
    if (previous && found != previous->keys.end() && *found == plan.keys[d])
    {
      plan.kept.push_back(d);
      plan.source.push_back(static_cast<int>(found - previous->keys.begin()));
    }
    else
    {
      plan.fresh.push_back(d);
    }
  }
  const int keptCount = static_cast<int>(plan.kept.size());
  plan.freshBase = keptCount == 0 || plan.fresh.empty() ? keptCount : paddedWidth(keptCount);
  plan.width = paddedWidth(plan.freshBase + static_cast<int>(plan.fresh.size()));
  plan.slot.assign(plan.keys.size(), 0);
  for (int q = 0; q < keptCount; ++q)
  {
    plan.slot[plan.kept[q]] = q;
  }
  for (std::size_t f = 0; f < plan.fresh.size(); ++f)
  {
    plan.slot[plan.fresh[f]] = plan.freshBase + static_cast<int>(f);
  }
  return plan;
}

void SparseCholesky::Implementation::reachOfColumns(const ColumnPlan& plan, LowRankFactor& out) const
{
  // L^-1 P u is nonzero only on the ancestors of u's rows. Leaves `offset` marked for the
  // reach's supernodes (the caller's Marks guard over out.supernodes clears them).
  std::vector<int> starts;
  for (const ColumnKey& key : plan.keys)
  {
    for (const auto& entry : key)
    {
      starts.push_back(this->supernodeOf[this->inversePermutation[entry.first]]);
    }
  }
  std::size_t rowCount = 0;
  this->reachOf(starts, out.supernodes, rowCount);
  out.rows = this->rowsOf(out.supernodes, rowCount);
  for (int node : out.supernodes)
  {
    out.firstRow.push_back(this->offset[node]);
  }
}

void SparseCholesky::Implementation::blocksOfColumns(const ColumnPlan& plan, LowRankFactor& out) const
{
  // y's columns are ordered by the first supernode of their reach (the supernodes are numbered
  // in a postorder of the elimination tree), so that the columns nonzero on a supernode, the
  // ones with a start in its subtree, form a range or nearly: the Gram matrix then sums, block
  // by block, only over a supernode's range (on the cube dumbbell at 100k, 12% of the dense
  // product's flops for 128 columns). Zeros inside a range add nothing. The order and the ranges
  // depend only on U's pattern and the factor.
  const int count = static_cast<int>(plan.keys.size());
  std::vector<std::vector<int>> starts(count);
  std::vector<int> order(count);
  std::vector<int> lowest(count, std::numeric_limits<int>::max());
  for (int d = 0; d < count; ++d)
  {
    for (const auto& entry : plan.keys[d])
    {
      starts[d].push_back(this->supernodeOf[this->inversePermutation[entry.first]]);
      lowest[d] = std::min(lowest[d], starts[d].back());
    }
    order[d] = d;
  }
  std::stable_sort(order.begin(), order.end(), [&lowest](int a, int b) { return lowest[a] < lowest[b]; });
  out.column.assign(count, 0);
  const std::size_t reachCount = out.supernodes.size();
  std::vector<int> first(reachCount, count), last(reachCount, -1);
  auto indexOf = [&out](int node) {
    return static_cast<std::size_t>(
      std::lower_bound(out.supernodes.begin(), out.supernodes.end(), node) - out.supernodes.begin());
  };
  for (int q = 0; q < count; ++q)
  {
    out.column[order[q]] = q;
    for (int start : starts[order[q]])
    {
      // Columns go in increasing q: a supernode whose last column is already q has been
      // reached by q from another start, and so have all its ancestors.
      for (int node = start; node >= 0; node = this->superParent[node])
      {
        const std::size_t i = indexOf(node);
        if (last[i] == q)
        {
          break;
        }
        first[i] = std::min(first[i], q);
        last[i] = q;
      }
    }
  }
  out.blocks.clear();
  for (std::size_t i = 0; i < reachCount; ++i)
  {
    const int node = out.supernodes[i];
    const int rowCount = this->super()[node + 1] - this->super()[node];
    if (!out.blocks.empty() && out.blocks.back().first == first[i] && out.blocks.back().last == last[i])
    {
      out.blocks.back().rowCount += rowCount;
    }
    else
    {
      out.blocks.push_back({ out.firstRow[i], rowCount, first[i], last[i] });
    }
  }
}

void SparseCholesky::Implementation::copyKeptColumns(
  const ColumnPlan& plan, const LowRankFactor* previous, const LowRankFactor& out, std::vector<double>& work) const
{
  // The sweep's rows: the kept columns from the last Y where a row is in its reach, else zero.
  const std::size_t width = static_cast<std::size_t>(plan.width);
  work.assign(out.rows.size() * width, 0.0);
  if (plan.kept.empty())
  {
    return;
  }
  const Marks lastMarks(this->lastOffset, previous->supernodes);
  for (std::size_t i = 0; i < previous->supernodes.size(); ++i)
  {
    this->lastOffset[previous->supernodes[i]] = previous->firstRow[i];
  }
  const std::size_t count = static_cast<std::size_t>(previous->count());
  for (std::size_t r = 0; r < out.rows.size(); ++r)
  {
    const int j = out.rows[r];
    const int node = this->supernodeOf[j];
    if (this->lastOffset[node] >= 0)
    {
      const double* from =
        previous->y.data() + static_cast<std::size_t>(this->lastOffset[node] + j - this->super()[node]) * count;
      double* row = work.data() + r * width;
      for (std::size_t q = 0; q < plan.kept.size(); ++q)
      {
        row[q] = from[previous->column[plan.source[q]]];
      }
    }
  }
}

void SparseCholesky::Implementation::scatterFreshColumns(const ColumnPlan& plan, std::vector<double>& work) const
{
  // P U's new columns into the sweep's rows.
  for (int d : plan.fresh)
  {
    for (const auto& entry : plan.keys[d])
    {
      work[static_cast<std::size_t>(this->position(this->inversePermutation[entry.first])) * plan.width +
        plan.slot[d]] += entry.second;
    }
  }
}

void SparseCholesky::Implementation::sweepFreshColumns(
  const ColumnPlan& plan, const LowRankFactor& out, std::vector<double>& work) const
{
  // Y = L^-1 P U on the new columns, supernode by supernode in ascending (topological) order: a
  // dense triangular solve with the diagonal block, then the update of the rows below it.
  this->scatterFreshColumns(plan, work);
  const std::size_t width = static_cast<std::size_t>(plan.width);
  std::vector<double*> targets;
  std::vector<int> chunks; // the chunks of new columns not zero on the supernode
  for (int node : out.supernodes)
  {
    const int columns = this->super()[node + 1] - this->super()[node];
    const int rows = this->pi()[node + 1] - this->pi()[node];
    double* ys = work.data() + static_cast<std::size_t>(this->offset[node]) * width;
    // A chunk that is zero on the supernode's rows stays zero and changes nothing below:
    // skipping it is exact.
    chunks.clear();
    for (int c0 = plan.freshBase; c0 < plan.width; c0 += ColumnChunk)
    {
      bool zero = true;
      for (int t = 0; t < columns && zero; ++t)
      {
        for (int c = 0; c < ColumnChunk; ++c)
        {
          zero = zero && ys[static_cast<std::size_t>(t) * width + c0 + c] == 0.0;
        }
      }
      if (!zero)
      {
        chunks.push_back(c0);
      }
    }
    if (chunks.empty())
    {
      continue;
    }
    targets.resize(static_cast<std::size_t>(rows - columns));
    for (int i = columns; i < rows; ++i)
    {
      targets[i - columns] =
        work.data() + static_cast<std::size_t>(this->position(this->rows()[this->pi()[node] + i])) * width;
    }
    forwardSupernode(this->values() + this->px()[node], rows, columns, rows, ys, targets.data(), plan.width,
      chunks.data(), static_cast<int>(chunks.size()));
  }
}

cholmod_factor* SparseCholesky::Implementation::simplicialFactor() const
{
  if (!this->simplicial)
  {
    this->simplicial = cholmod_copy_factor(this->factor, this->mutableCommon());
    if (!this->simplicial || !cholmod_change_factor(CHOLMOD_REAL, 1, 0, 0, 0, this->simplicial, this->mutableCommon()))
    {
      throw Error("the factor could not be converted to simplicial form");
    }
  }
  return this->simplicial;
}

void SparseCholesky::Implementation::solveFreshColumnsOneByOne(const ColumnPlan& plan, std::vector<double>& work) const
{
  // One cholmod_solve2 per new column with its entries as the sparse right-hand side (Bset): L x
  // = P u over x's pattern, on a simplicial copy of the factor (Bset needs one).
  cholmod_factor* simplicial = this->simplicialFactor();
  const std::size_t n = this->factor->n;
  std::vector<double> rhs(n, 0.0);
  std::vector<int> setRows;
  int setPointers[2];
  for (int d : plan.fresh)
  {
    setRows.clear();
    for (const auto& entry : plan.keys[d])
    {
      const int j = this->inversePermutation[entry.first];
      rhs[j] += entry.second;
      setRows.push_back(j);
    }
    cholmod_sparse set = cholmodPattern(n, setRows, setPointers);
    cholmod_dense b = cholmodView(rhs.data(), n);
    if (!cholmod_solve2(CHOLMOD_L, simplicial, &b, &set, &this->solveX, &this->solveXset, &this->solveY, &this->solveE,
          this->mutableCommon()))
    {
      throw Error("the sparse solve failed");
    }
    const int* pattern = static_cast<const int*>(this->solveXset->i);
    const int count = static_cast<const int*>(this->solveXset->p)[1];
    const double* x = static_cast<const double*>(this->solveX->x);
    for (int e = 0; e < count; ++e)
    {
      work[static_cast<std::size_t>(this->position(pattern[e])) * plan.width + plan.slot[d]] = x[pattern[e]];
    }
    for (int j : setRows)
    {
      rhs[j] = 0.0;
    }
  }
}

void SparseCholesky::Implementation::solveFreshColumnsTogether(const ColumnPlan& plan, std::vector<double>& work) const
{
  // cholmod_spsolve on all new columns: it solves dense blocks of four and keeps the nonzeros.
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t f = 0; f < plan.fresh.size(); ++f)
  {
    for (const auto& entry : plan.keys[plan.fresh[f]])
    {
      entries.emplace_back(this->inversePermutation[entry.first], static_cast<int>(f), entry.second);
    }
  }
  Eigen::SparseMatrix<double> permuted(
    static_cast<Eigen::Index>(this->factor->n), static_cast<Eigen::Index>(plan.fresh.size()));
  permuted.setFromTriplets(entries.begin(), entries.end());
  permuted.makeCompressed();
  cholmod_sparse b = cholmodView(permuted, 0);
  cholmod_sparse* x = cholmod_spsolve(CHOLMOD_L, this->factor, &b, this->mutableCommon());
  if (!x)
  {
    throw Error("the sparse solve failed");
  }
  const int* xp = static_cast<const int*>(x->p);
  const int* xi = static_cast<const int*>(x->i);
  const double* xx = static_cast<const double*>(x->x);
  for (std::size_t f = 0; f < plan.fresh.size(); ++f)
  {
    for (int e = xp[f]; e < xp[f + 1]; ++e)
    {
      work[static_cast<std::size_t>(this->position(xi[e])) * plan.width + plan.slot[plan.fresh[f]]] = xx[e];
    }
  }
  cholmod_free_sparse(&x, this->mutableCommon());
}

void SparseCholesky::Implementation::keepDistinctColumns(
  const ColumnPlan& plan, const std::vector<double>& work, LowRankFactor& out)
{
  // Y row by row in the order of out.column, whatever the sweep's layout was (+ 0.0 makes every
  // zero positive).
  out.keys = plan.keys;
  out.distinct = plan.distinct;
  const std::size_t count = plan.keys.size();
  std::vector<int> slotOfColumn(count);
  for (std::size_t d = 0; d < count; ++d)
  {
    slotOfColumn[static_cast<std::size_t>(out.column[d])] = plan.slot[d];
  }
  out.y.resize(out.rows.size() * count);
  for (std::size_t r = 0; r < out.rows.size(); ++r)
  {
    const double* from = work.data() + r * static_cast<std::size_t>(plan.width);
    double* to = out.y.data() + r * count;
    for (std::size_t q = 0; q < count; ++q)
    {
      to[q] = from[slotOfColumn[q]] + 0.0;
    }
  }
}

Eigen::MatrixXd SparseCholesky::Implementation::gramOf(const LowRankFactor& out)
{
  // U^T A^-1 U = Y^T Y by the BLAS (syrk), block by block in y's row order, each block on its
  // range of columns only. The columns' order, the blocks and the order of the sums depend only
  // on U's distinct columns and the factor: every U with the same columns, in any order and
  // whatever the last prepare() kept, gives the same matrix, so the entries depend only on U.
  const int count = out.count();
  Eigen::MatrixXd product = Eigen::MatrixXd::Zero(count, count);
  const char lower = 'L', plain = 'N';
  const double one = 1.0;
  for (const LowRankFactor::Block& block : out.blocks)
  {
    const int width = block.last - block.first + 1;
    dsyrk_(&lower, &plain, &width, &block.rowCount, &one,
      out.y.data() + static_cast<std::size_t>(block.firstRow) * count + block.first, &count, &one,
      product.data() + static_cast<Eigen::Index>(block.first) * (count + 1), &count);
  }
  const int k = static_cast<int>(out.distinct.size());
  Eigen::MatrixXd gram(k, k);
  for (int a = 0; a < k; ++a)
  {
    for (int b = 0; b < k; ++b)
    {
      const int i = out.column[out.distinct[a]], j = out.column[out.distinct[b]];
      gram(a, b) = product(std::max(i, j), std::min(i, j)) + 0.0;
    }
  }
  return gram;
}

SparseCholesky::LowRank SparseCholesky::prepare(const Eigen::SparseMatrix<double>& U, LowRankRoute route) const
{
  const Implementation& m = *this->Impl;
  if (!m.factor || U.rows() != static_cast<Eigen::Index>(m.factor->n))
  {
    throw Error("the low-rank term does not match the factored matrix");
  }
  checkFinite(U);
  const bool sweep = route == LowRankRoute::SupernodalSweep;
  const std::shared_ptr<const LowRankFactor> previous = sweep ? m.last : nullptr;
  const ColumnPlan plan = Implementation::planColumns(U, previous.get());
  auto factor = std::make_shared<LowRankFactor>();
  LowRankFactor& out = *factor;
  out.generation = m.generation;
  const Marks reachMarks(m.offset, out.supernodes);
  m.reachOfColumns(plan, out);
  m.blocksOfColumns(plan, out);
  std::vector<double> work;
  m.copyKeptColumns(plan, previous.get(), out, work);
  if (!plan.fresh.empty())
  {
    switch (route)
    {
      case LowRankRoute::SupernodalSweep:
        m.sweepFreshColumns(plan, out, work);
        break;
      case LowRankRoute::CholmodSolve2:
        m.solveFreshColumnsOneByOne(plan, work);
        break;
      case LowRankRoute::CholmodSpsolve:
        m.solveFreshColumnsTogether(plan, work);
        break;
    }
  }
  Implementation::keepDistinctColumns(plan, work, out);
  LowRank result;
  result.gram = Implementation::gramOf(out);
  result.reachRows = out.rows.size();
  for (const LowRankFactor::Block& block : out.blocks)
  {
    const std::size_t width = static_cast<std::size_t>(block.last - block.first + 1);
    result.gramProducts += static_cast<std::size_t>(block.rowCount) * width * (width + 1) / 2;
  }
  result.factor = factor;
  if (sweep)
  {
    m.last = factor;
  }
  return result;
}

Eigen::VectorXd SparseCholesky::apply(const LowRank& lowRank, const Eigen::VectorXd& s) const
{
  const Implementation& m = *this->Impl;
  if (!m.factor || !lowRank.factor || lowRank.factor->generation != m.generation ||
    s.size() != static_cast<Eigen::Index>(lowRank.factor->distinct.size()))
  {
    throw Error("the low-rank term does not belong to this factorization or has another size");
  }
  const LowRankFactor& f = *lowRank.factor;
  const int n = static_cast<int>(m.factor->n);
  // z = Y s on the reach (s summed over equal columns in U's order), then P^T L^-T z with the
  // supernodal backward solve.
  Eigen::VectorXd t = Eigen::VectorXd::Zero(f.count());
  for (Eigen::Index c = 0; c < s.size(); ++c)
  {
    t[f.column[f.distinct[c]]] += s[c];
  }
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> y(
    f.y.data(), static_cast<Eigen::Index>(f.rows.size()), f.count());
  const Eigen::VectorXd reach = y * t;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  for (std::size_t r = 0; r < f.rows.size(); ++r)
  {
    z[f.rows[r]] = reach[static_cast<Eigen::Index>(r)];
  }
  SupernodalSolve::backward(*m.factor, z.data(), m.solveWork);
  const double* x = z.data();
  const int* perm = static_cast<const int*>(m.factor->Perm);
  Eigen::VectorXd out(n);
  for (int r = 0; r < n; ++r)
  {
    out[perm[r]] = x[r] + 0.0;
  }
  return out;
}

#else

/// A^-1 U.
struct SparseCholesky::LowRankFactor
{
  Eigen::MatrixXd inverseU;
  std::uint64_t generation = 0; ///< the factorization it belongs to
};

struct SparseCholesky::Implementation
{
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool ready = false;
  std::uint64_t generation = 0; // counts factorizations
};

SparseCholesky::SparseCholesky()
  : Impl(new Implementation)
{
}

SparseCholesky::~SparseCholesky() = default;

std::string SparseCholesky::backend()
{
  return "Eigen SimplicialLDLT";
}

void SparseCholesky::setSupernodalRoute(SupernodalRoute) {}

std::size_t SparseCholesky::factorNonZeros() const
{
  return this->Impl->ready ? static_cast<std::size_t>(this->Impl->solver.matrixL().nestedExpression().nonZeros()) : 0;
}

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A, const std::vector<int>& permutation)
{
  if (permutation.size() != static_cast<std::size_t>(A.rows()))
  {
    throw Error("a fill-reducing permutation needs one entry per row (" + std::to_string(A.rows()) + ")");
  }
  return this->factor(A); // Eigen's solver orders by itself
}

std::vector<int> SparseCholesky::permutation() const
{
  return {};
}

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A, Ordering)
{
  Implementation& m = *this->Impl;
  ++m.generation;
  m.solver.compute(A);
  m.ready = m.solver.info() == Eigen::Success && (m.solver.vectorD().array() > 0.0).all();
  return m.ready;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const
{
  return this->solveColumns(b);
}

Eigen::MatrixXd SparseCholesky::solveColumns(const Eigen::MatrixXd& b) const
{
  if (!this->Impl->ready)
  {
    throw Error("no factorization to solve with");
  }
  if (b.rows() != this->Impl->solver.rows())
  {
    throw Error("the right-hand side does not match the factored matrix");
  }
  return this->Impl->solver.solve(b);
}

Eigen::MatrixXd SparseCholesky::solveBlock(const Eigen::MatrixXd& b) const
{
  return this->solveColumns(b);
}

SparseCholesky::LowRank SparseCholesky::prepare(const Eigen::SparseMatrix<double>& U, LowRankRoute) const
{
  const Implementation& m = *this->Impl;
  if (!m.ready || U.rows() != m.solver.rows())
  {
    throw Error("the low-rank term does not match the factored matrix");
  }
  checkFinite(U);
  auto factor = std::make_shared<LowRankFactor>();
  factor->inverseU = m.solver.solve(Eigen::MatrixXd(U)); // one solve per column
  factor->generation = m.generation;
  LowRank out;
  const Eigen::MatrixXd gram = U.transpose() * factor->inverseU;
  out.gram = 0.5 * (gram + gram.transpose()); // exactly symmetric
  out.gramProducts = static_cast<std::size_t>(U.nonZeros()) * static_cast<std::size_t>(U.cols());
  out.reachRows = static_cast<std::size_t>(U.rows()); // dense solves: every row can be nonzero
  out.factor = factor;
  return out;
}

Eigen::VectorXd SparseCholesky::apply(const LowRank& lowRank, const Eigen::VectorXd& s) const
{
  if (!this->Impl->ready || !lowRank.factor || lowRank.factor->generation != this->Impl->generation ||
    s.size() != lowRank.factor->inverseU.cols())
  {
    throw Error("the low-rank term does not belong to this factorization or has another size");
  }
  return lowRank.factor->inverseU * s;
}

#endif

} // namespace kerf
