// CHOLMOD-backed sparse Cholesky with sparse multi-column forward solves for low-rank corrections.
#include "Harmonic/SparseCholesky.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

#ifdef KERF_HAVE_CHOLMOD
#include <cholmod.h>
#include <dlfcn.h>
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
// A cholmod_sparse view of a compressed column-major Eigen matrix (no copy).
cholmod_sparse cholmodView(const Eigen::SparseMatrix<double>& A, int stype)
{
  cholmod_sparse s{};
  s.nrow = static_cast<std::size_t>(A.rows());
  s.ncol = static_cast<std::size_t>(A.cols());
  s.nzmax = static_cast<std::size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = stype;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

cholmod_dense cholmodView(const double* values, std::size_t n)
{
  cholmod_dense d{};
  d.nrow = n;
  d.ncol = 1;
  d.nzmax = n;
  d.d = n;
  d.x = const_cast<double*>(values);
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

// Dense kernels of the supernodal forward solve and of the Gram matrix, on row-major blocks of
// right-hand sides padded to a multiple of ColumnChunk columns. Every right-hand side sees the
// same arithmetic in the same order whatever the others are, so a column's values do not depend
// on which columns are solved with it. Each kernel is compiled for AVX-512, AVX2 with FMA and
// the x86-64 baseline; the processor picks one when the library loads.
constexpr int ColumnChunk = 8;
constexpr int TileRows = 8;
typedef double Chunk __attribute__((vector_size(ColumnChunk * sizeof(double))));
// The kernels inline their vector helpers, so no vector crosses a call boundary.
#pragma GCC diagnostic ignored "-Wpsabi"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define KERF_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define KERF_VECTOR_CLONES
#endif
#define KERF_INLINE inline __attribute__((always_inline))

KERF_INLINE Chunk loadChunk(const double* p)
{
  Chunk v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

KERF_INLINE void storeChunk(double* p, const Chunk& v)
{
  __builtin_memcpy(p, &v, sizeof v);
}

// Y_i -= sum_{t < depth} L(i, t) y[t] for rows [begin, end) of a block whose columns start at
// `block` (leading dimension ld), on one chunk of columns; row i's values start at target(i).
template <int Depth, typename Target>
KERF_INLINE void subtractBlock(const double* block, std::size_t ld, int depth, const Chunk* y, int begin, int end, Target target)
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
void forwardSupernode(const double* L, int ld, int columns, int rows, double* Ys, double* const* targets,
  int width, const int* chunks, int chunkCount)
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

// One supernode of the backward solve L^T x = z: with x already known on the rows below the
// diagonal block (gathered into g[columns .. rows)) and g[0 .. columns) = z on the block's rows,
// x_t = (z_t - sum_{i>t} L(i,t) x_i) / L(t,t) for t = columns-1 .. 0, left in g. L is the
// supernode's column-major block with leading dimension ld. Columns go in blocks of TileRows,
// whose dot products with the rows below the block stream their columns together.
KERF_VECTOR_CLONES
void backwardSupernode(const double* L, int ld, int columns, int rows, double* g)
{
  const std::size_t stride = static_cast<std::size_t>(ld);
  for (int end = columns; end > 0; end -= TileRows)
  {
    const int t0 = std::max(0, end - TileRows);
    const int depth = end - t0;
    // sums[t] = sum_{i >= end} L(i, t0 + t) x_i: ColumnChunk-wide partial sums, reduced lane by
    // lane, then the remaining rows.
    Chunk acc[TileRows];
    for (int t = 0; t < TileRows; ++t)
    {
      acc[t] = Chunk{};
    }
    int i = end;
    for (; i + ColumnChunk <= rows; i += ColumnChunk)
    {
      const Chunk x = loadChunk(g + i);
      for (int t = 0; t < depth; ++t)
      {
        acc[t] += loadChunk(L + (t0 + t) * stride + i) * x;
      }
    }
    double sums[TileRows];
    for (int t = 0; t < depth; ++t)
    {
      double sum = 0.0;
      for (int c = 0; c < ColumnChunk; ++c)
      {
        sum += acc[t][c];
      }
      for (int j = i; j < rows; ++j)
      {
        sum += L[(t0 + t) * stride + j] * g[j];
      }
      sums[t] = sum;
    }
    // The block's own triangle.
    for (int t = end - 1; t >= t0; --t)
    {
      const double* column = L + t * stride;
      double value = g[t] - sums[t - t0];
      for (int j = t + 1; j < end; ++j)
      {
        value -= column[j] * g[j];
      }
      g[t] = value / column[t];
    }
  }
}

// gram(c + q, j) += sum_{r in [r0, r1)} Y(r, c + q) Y(r, j) for q < 4 and the `Chunks` chunks
// of columns from j0, continuing each entry's sum in ascending r.
template <int Chunks>
KERF_INLINE void gramTile(const double* Y, std::size_t r0, std::size_t r1, int width, int c, int j0, double* gram)
{
  constexpr int Columns = 4;
  Chunk acc[Columns][Chunks];
  for (int q = 0; q < Columns; ++q)
  {
    for (int h = 0; h < Chunks; ++h)
    {
      acc[q][h] = loadChunk(gram + static_cast<std::size_t>(c + q) * width + j0 + h * ColumnChunk);
    }
  }
  for (std::size_t r = r0; r < r1; ++r)
  {
    const double* yr = Y + r * width;
    Chunk y[Chunks];
    for (int h = 0; h < Chunks; ++h)
    {
      y[h] = loadChunk(yr + j0 + h * ColumnChunk);
    }
    for (int q = 0; q < Columns; ++q)
    {
      for (int h = 0; h < Chunks; ++h)
      {
        acc[q][h] += yr[c + q] * y[h];
      }
    }
  }
  for (int q = 0; q < Columns; ++q)
  {
    for (int h = 0; h < Chunks; ++h)
    {
      storeChunk(gram + static_cast<std::size_t>(c + q) * width + j0 + h * ColumnChunk, acc[q][h]);
    }
  }
}

// The upper triangle (by chunks) of Y^T Y: gram(c, j) = sum_r Y(r,c) Y(r,j), each entry summed
// in ascending r, for the `width` columns of Y (a multiple of ColumnChunk); gram (width x width)
// starts at zero. Row blocks keep Y in cache; a block where four columns are all zero only adds
// exact zeros to their rows and is skipped.
KERF_VECTOR_CLONES
void upperGram(const double* Y, std::size_t rows, int width, double* gram)
{
  constexpr std::size_t BlockRows = 32;
  for (std::size_t r0 = 0; r0 < rows; r0 += BlockRows)
  {
    const std::size_t r1 = std::min(rows, r0 + BlockRows);
    for (int c = 0; c < width; c += 4)
    {
      bool zero = true;
      for (std::size_t r = r0; r < r1 && zero; ++r)
      {
        const double* yr = Y + r * width + c;
        zero = yr[0] == 0.0 && yr[1] == 0.0 && yr[2] == 0.0 && yr[3] == 0.0;
      }
      if (zero)
      {
        continue;
      }
      int j0 = c / ColumnChunk * ColumnChunk;
      for (; j0 + 2 * ColumnChunk <= width; j0 += 2 * ColumnChunk)
      {
        gramTile<2>(Y, r0, r1, width, c, j0, gram);
      }
      if (j0 < width)
      {
        gramTile<1>(Y, r0, r1, width, c, j0, gram);
      }
    }
  }
}

// CHOLMOD's supernodal factorization runs a few memory copies in OpenMP parallel regions with a
// fixed team size. On small machines their synchronisation costs more than it saves (a
// 100k-triangle factorization takes twice as long on two cores), so while one is alive the
// OpenMP runtime CHOLMOD loaded, if any, runs parallel regions on the calling thread. The
// factor is the same either way.
class SerialOpenMP
{
public:
  SerialOpenMP()
    : Get(reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels")))
    , Set(reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")))
  {
    if (this->Get && this->Set)
    {
      this->Previous = this->Get();
      this->Set(0);
    }
  }
  ~SerialOpenMP()
  {
    if (this->Get && this->Set)
    {
      this->Set(this->Previous);
    }
  }
  SerialOpenMP(const SerialOpenMP&) = delete;
  SerialOpenMP& operator=(const SerialOpenMP&) = delete;

private:
  int (*Get)() = nullptr;
  void (*Set)(int) = nullptr;
  int Previous = 1;
};

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
} // namespace

/// Y = L^-1 P U on its reach, for apply() and for the next prepare().
struct SparseCholesky::LowRankFactor
{
  using Key = std::vector<std::pair<int, double>>; ///< a column's entries
  std::vector<std::pair<Key, int>> keys; ///< each column of U and its column in y
  std::vector<int> column;               ///< U's column -> its column in y
  std::vector<int> supernodes;           ///< the reach, ascending
  std::vector<int> firstRow;             ///< each reach supernode's first row in y
  std::vector<int> rows;                 ///< the permuted row of each row of y
  int width = 0;                         ///< values per row of y (a multiple of ColumnChunk)
  std::vector<double> y;                 ///< row-major
  std::uint64_t generation = 0;          ///< the factorization it belongs to
};

struct SparseCholesky::Implementation
{
  cholmod_common common;
  cholmod_factor* factor = nullptr; // supernodal L L^T after factor()
  std::vector<int> inversePermutation; // original row -> permuted row
  std::vector<int> supernodeOf;        // permuted row -> its supernode
  std::vector<int> superParent;        // supernodal elimination tree
  mutable std::vector<int> offset;     // workspace: supernode -> first row in a reach, or -1
  mutable std::vector<int> lastOffset; // workspace: supernode -> first row in last's reach, or -1
  // The last prepare()'s Y: a U that keeps some of its columns (a refined cut) only solves for
  // the new ones. Each column's values do not depend on the others solved with it, so reuse
  // gives the same bits as solving afresh.
  mutable std::shared_ptr<const LowRankFactor> last;
  std::uint64_t generation = 0; // counts factorizations, so a LowRank knows which it belongs to

  Implementation()
  {
    cholmod_start(&this->common);
    this->common.print = 0;
    this->common.error_handler = nullptr;
  }
  ~Implementation()
  {
    if (this->factor)
    {
      cholmod_free_factor(&this->factor, &this->common);
    }
    cholmod_finish(&this->common);
  }

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

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A)
{
  Implementation& m = *this->Impl;
  if (m.factor)
  {
    cholmod_free_factor(&m.factor, &m.common);
  }
  m.last.reset();
  ++m.generation;
  Eigen::SparseMatrix<double> compressed = A;
  compressed.makeCompressed();
  cholmod_sparse s = cholmodView(compressed, -1);
  // Nested dissection (METIS): less fill than AMD on surface meshes, so shorter reaches.
  m.common.nmethods = 1;
  m.common.method[0].ordering = CHOLMOD_METIS;
  m.common.supernodal = CHOLMOD_SUPERNODAL;
  m.factor = cholmod_analyze(&s, &m.common);
  if (!m.factor)
  {
    return false;
  }
  bool factored = false;
  {
    const SerialOpenMP serial;
    factored = cholmod_factorize(&s, m.factor, &m.common) != 0;
  }
  if (!factored || m.common.status != CHOLMOD_OK ||
    m.factor->minor < m.factor->n || !m.factor->is_super)
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

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const
{
  Implementation& m = *this->Impl;
  if (!m.factor)
  {
    throw Error("no factorization to solve with");
  }
  cholmod_dense rhs = cholmodView(b.data(), static_cast<std::size_t>(b.size()));
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, m.factor, &rhs, &m.common);
  if (!x)
  {
    throw Error("the sparse solve failed");
  }
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &m.common);
  return out;
}

SparseCholesky::LowRank SparseCholesky::prepare(const Eigen::SparseMatrix<double>& U) const
{
  const Implementation& m = *this->Impl;
  if (!m.factor || U.rows() != static_cast<Eigen::Index>(m.factor->n))
  {
    throw Error("the low-rank term does not match the factored matrix");
  }
  const int k = static_cast<int>(U.cols());
  checkFinite(U);
  auto factor = std::make_shared<LowRankFactor>();
  LowRankFactor& out = *factor;
  out.generation = m.generation;
  const std::shared_ptr<const LowRankFactor> previous = m.last;

  // Each column's key is its entries. Columns of the last call keep their values and come first;
  // the new ones follow from a whole chunk on, so the sweep touches only theirs.
  std::map<LowRankFactor::Key, int> lastColumn;
  if (previous)
  {
    for (const auto& keyed : previous->keys)
    {
      lastColumn.emplace(keyed.first, keyed.second);
    }
  }
  std::vector<LowRankFactor::Key> keys(k);
  std::vector<int> kept, fresh, source; // source: the kept columns' places in the last Y
  for (int c = 0; c < k; ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(U, c); it; ++it)
    {
      keys[c].emplace_back(static_cast<int>(it.row()), it.value());
    }
    const auto found = lastColumn.find(keys[c]);
    if (found != lastColumn.end())
    {
      kept.push_back(c);
      source.push_back(found->second);
    }
    else
    {
      fresh.push_back(c);
    }
  }
  const int keptCount = static_cast<int>(kept.size());
  const int freshBase = keptCount == 0 || fresh.empty() ? keptCount : paddedWidth(keptCount);
  out.width = paddedWidth(freshBase + static_cast<int>(fresh.size()));
  out.column.assign(k, 0);
  for (int q = 0; q < keptCount; ++q)
  {
    out.column[kept[q]] = q;
  }
  for (std::size_t f = 0; f < fresh.size(); ++f)
  {
    out.column[fresh[f]] = freshBase + static_cast<int>(f);
  }
  for (int c = 0; c < k; ++c)
  {
    out.keys.emplace_back(keys[c], out.column[c]);
  }

  // The reach: L^-1 P u is nonzero only on the ancestors of u's rows.
  std::vector<int> starts;
  for (const LowRankFactor::Key& key : keys)
  {
    for (const auto& entry : key)
    {
      starts.push_back(m.supernodeOf[m.inversePermutation[entry.first]]);
    }
  }
  std::size_t rowCount = 0;
  const Marks reachMarks(m.offset, out.supernodes);
  m.reachOf(starts, out.supernodes, rowCount);
  out.rows = m.rowsOf(out.supernodes, rowCount);
  for (int node : out.supernodes)
  {
    out.firstRow.push_back(m.offset[node]);
  }
  const std::vector<int>& reach = out.supernodes;
  const std::size_t width = static_cast<std::size_t>(out.width);

  // Y row by row: the kept columns from the last Y where a row is in its reach, else zero.
  out.y.resize(rowCount * width);
  {
    static const std::vector<int> none;
    const Marks lastMarks(m.lastOffset, previous ? previous->supernodes : none);
    if (previous)
    {
      for (std::size_t i = 0; i < previous->supernodes.size(); ++i)
      {
        m.lastOffset[previous->supernodes[i]] = previous->firstRow[i];
      }
    }
    for (std::size_t r = 0; r < rowCount; ++r)
    {
      double* row = out.y.data() + r * width;
      std::fill(row, row + width, 0.0);
      const int j = out.rows[r];
      const int node = m.supernodeOf[j];
      if (keptCount > 0 && m.lastOffset[node] >= 0)
      {
        const double* from = previous->y.data() +
          static_cast<std::size_t>(m.lastOffset[node] + j - m.super()[node]) * static_cast<std::size_t>(previous->width);
        for (int q = 0; q < keptCount; ++q)
        {
          row[q] = from[source[q]];
        }
      }
    }
  }

  // New columns: Y = L^-1 P U, supernode by supernode in ascending (topological) order: a dense
  // triangular solve with the diagonal block, then the update of the rows below it.
  if (!fresh.empty())
  {
    for (int c : fresh)
    {
      for (const auto& entry : keys[c])
      {
        out.y[static_cast<std::size_t>(m.position(m.inversePermutation[entry.first])) * width + out.column[c]] += entry.second;
      }
    }
    std::vector<double*> targets;
    std::vector<int> chunks; // the chunks of new columns not zero on the supernode
    for (int node : reach)
    {
      const int columns = m.super()[node + 1] - m.super()[node];
      const int rows = m.pi()[node + 1] - m.pi()[node];
      double* ys = out.y.data() + static_cast<std::size_t>(m.offset[node]) * width;
      // A chunk that is zero on the supernode's rows stays zero and changes nothing below:
      // skipping it is exact.
      chunks.clear();
      for (int c0 = freshBase; c0 < out.width; c0 += ColumnChunk)
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
        targets[i - columns] = out.y.data() + static_cast<std::size_t>(m.position(m.rows()[m.pi()[node] + i])) * width;
      }
      forwardSupernode(m.values() + m.px()[node], rows, columns, rows, ys, targets.data(), out.width,
        chunks.data(), static_cast<int>(chunks.size()));
    }
  }

  // U^T A^-1 U = Y^T Y, in U's column order (+ 0.0 makes every zero positive, so skipped zero
  // blocks cannot show in the sign of a zero).
  std::vector<double> gram(width * width, 0.0);
  upperGram(out.y.data(), rowCount, out.width, gram.data());
  LowRank result;
  result.gram.resize(k, k);
  for (int a = 0; a < k; ++a)
  {
    for (int b = 0; b < k; ++b)
    {
      const int i = std::min(out.column[a], out.column[b]);
      const int j = std::max(out.column[a], out.column[b]);
      result.gram(a, b) = gram[static_cast<std::size_t>(i) * width + j] + 0.0;
    }
  }
  m.last = factor;
  result.factor = factor;
  return result;
}

Eigen::VectorXd SparseCholesky::apply(const LowRank& lowRank, const Eigen::VectorXd& s) const
{
  const Implementation& m = *this->Impl;
  if (!m.factor || !lowRank.factor || lowRank.factor->generation != m.generation ||
    s.size() != static_cast<Eigen::Index>(lowRank.factor->column.size()))
  {
    throw Error("the low-rank term does not belong to this factorization or has another size");
  }
  const LowRankFactor& f = *lowRank.factor;
  const int n = static_cast<int>(m.factor->n);
  // z = Y s on the reach (summed in U's column order, wherever a column sits in y), then
  // P^T L^-T z.
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  const int k = static_cast<int>(f.column.size());
  for (std::size_t r = 0; r < f.rows.size(); ++r)
  {
    const double* row = f.y.data() + r * static_cast<std::size_t>(f.width);
    double value = 0.0;
    for (int c = 0; c < k; ++c)
    {
      value += row[f.column[c]] * s[c];
    }
    z[f.rows[r]] = value;
  }
  // Supernodes from the root down: each one's rows below its diagonal block are solved.
  std::vector<double> g;
  for (int node = static_cast<int>(m.factor->nsuper) - 1; node >= 0; --node)
  {
    const int first = m.super()[node];
    const int columns = m.super()[node + 1] - first;
    const int rows = m.pi()[node + 1] - m.pi()[node];
    const int* pattern = m.rows() + m.pi()[node];
    g.resize(static_cast<std::size_t>(rows));
    for (int i = 0; i < rows; ++i)
    {
      g[i] = z[pattern[i]];
    }
    backwardSupernode(m.values() + m.px()[node], rows, columns, rows, g.data());
    for (int t = 0; t < columns; ++t)
    {
      z[first + t] = g[t];
    }
  }
  const int* perm = static_cast<const int*>(m.factor->Perm);
  Eigen::VectorXd out(n);
  for (int r = 0; r < n; ++r)
  {
    out[perm[r]] = z[r] + 0.0;
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

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A)
{
  Implementation& m = *this->Impl;
  ++m.generation;
  m.solver.compute(A);
  m.ready = m.solver.info() == Eigen::Success && (m.solver.vectorD().array() > 0.0).all();
  return m.ready;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const
{
  if (!this->Impl->ready)
  {
    throw Error("no factorization to solve with");
  }
  return this->Impl->solver.solve(b);
}

SparseCholesky::LowRank SparseCholesky::prepare(const Eigen::SparseMatrix<double>& U) const
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
