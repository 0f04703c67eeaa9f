// Huge-page work buffers: the allocator's blocks, the advice the kernel records for them, and the
// CHOLMOD allocator that Kerf's analyses and factorizations install while they run.
#include "Mesh/MeshGenerators.h"
#include "Numerics/HugePages.h"
#include "Numerics/LaplacianWeights.h"
#include "Numerics/SupernodalFactorization.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace kerf;

namespace
{

constexpr std::uintptr_t HugePage = std::uintptr_t(2) << 20;

// Where the kernel can back memory with transparent huge pages on request (Linux, THP not "never").
bool systemOffersHugePages()
{
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(setting, text);
  return text.find("[always]") != std::string::npos || text.find("[madvise]") != std::string::npos;
}

// The VmFlags of the mapping holding `address` in /proc/self/smaps ("hg": advised for huge pages).
std::string mappingFlags(const void* address)
{
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' '))
    {
      inside = begin <= a && a < end;
    }
    else if (inside && line.rfind("VmFlags:", 0) == 0)
    {
      return line.substr(8);
    }
  }
  return "";
}

bool advisedForHugePages(const void* address)
{
  std::istringstream flags(mappingFlags(address));
  std::string flag;
  while (flags >> flag)
  {
    if (flag == "hg")
    {
      return true;
    }
  }
  return false;
}

} // namespace

TEST(HugePages, LargeBlocksAreAlignedAdvisedAndHoldTheirValues)
{
  const std::size_t n = (std::size_t(5) << 20) / sizeof(double) + 3; // 5 MiB and a bit
  HugePageAllocator<double> allocator;
  double* block = allocator.allocate(n);
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % HugePage, 0u);
  for (std::size_t i = 0; i < n; ++i)
  {
    block[i] = static_cast<double>(i) * 0.5;
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    sum += block[i];
  }
  EXPECT_EQ(sum, 0.25 * static_cast<double>(n) * static_cast<double>(n - 1));
  if (systemOffersHugePages())
  {
    EXPECT_TRUE(advisedForHugePages(block)) << mappingFlags(block);
    EXPECT_TRUE(advisedForHugePages(block + n - 1)) << mappingFlags(block + n - 1);
  }
  allocator.deallocate(block, n);
}

TEST(HugePages, SmallBlocksAreUsableAndOversizedRequestsThrow)
{
  HugePageAllocator<int> allocator;
  const std::size_t n = HugePageMinimumBytes / sizeof(int) - 1;
  int* block = allocator.allocate(n);
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(block) % alignof(std::max_align_t), 0u);
  block[0] = 1;
  block[n - 1] = 2;
  EXPECT_EQ(block[0] + block[n - 1], 3);
  allocator.deallocate(block, n);
  EXPECT_THROW(allocator.allocate(static_cast<std::size_t>(-1) / 2), std::bad_array_new_length);
}

TEST(HugePages, VectorsGrowAcrossTheThresholdAndCopyLikeStdVector)
{
  HugePageVector<int> grown;
  std::vector<int> expected;
  for (int i = 0; i < 3000000; ++i) // 12 MB: the growth crosses 2 MiB on the way
  {
    grown.push_back(i * 7 - 5);
    expected.push_back(i * 7 - 5);
  }
  ASSERT_EQ(grown.size(), expected.size());
  EXPECT_TRUE(std::equal(grown.begin(), grown.end(), expected.begin()));
  const HugePageVector<int> copy = grown;
  EXPECT_TRUE(copy == grown);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(copy.data()) % HugePage, 0u);
  grown.resize(10);
  grown.shrink_to_fit();
  EXPECT_EQ(std::accumulate(grown.begin(), grown.end(), 0), 7 * 45 - 50);
}

TEST(HugePages, AdviceOnAnyRangeIsHarmless)
{
  adviseHugePages(nullptr, std::size_t(8) << 20);
  std::vector<char> small(4096, 1);
  adviseHugePages(small.data(), small.size());
  std::vector<char> unaligned((std::size_t(3) << 20) + 123, 2); // may hold no whole huge page
  adviseHugePages(unaligned.data() + 1, unaligned.size() - 1);
  EXPECT_EQ(small[4095] + unaligned.back(), 3);
}

#ifdef KERF_HAVE_CHOLMOD
TEST(HugePages, CHOLMODFactorValuesTakeHugePagesInKerfsFactorization)
{
  EXPECT_FALSE(cholmodAllocatorInstalled()) << "SuiteSparse's allocator is Kerf's outside Kerf's calls";
  // A 160 x 160 grid: its supernodal factor's values are several MiB.
  const TriangleMesh mesh = makeGrid(1.0, 1.0, 160, 160);
  Eigen::SparseMatrix<double> laplacian =
    assembleLaplacian(mesh, computeLaplacianWeights(mesh, LaplacianWeightOptions()));
  Eigen::SparseMatrix<double> identity(laplacian.rows(), laplacian.cols());
  identity.setIdentity();
  Eigen::SparseMatrix<double> lower = (laplacian + 1e-3 * identity).triangularView<Eigen::Lower>();
  lower.makeCompressed();

  cholmod_common common;
  ASSERT_TRUE(startCholmod(&common));
  common.supernodal = CHOLMOD_SUPERNODAL;
  cholmod_sparse a = cholmodView(lower, -1);
  cholmod_factor* factor = cholmod_analyze(&a, &common);
  ASSERT_NE(factor, nullptr);
  ASSERT_TRUE(factorizeSupernodal(&a, factor, &common));
  EXPECT_FALSE(cholmodAllocatorInstalled()) << "the factorization put SuiteSparse's allocator back";
  ASSERT_EQ(factor->minor, factor->n);
  ASSERT_GE(factor->xsize * sizeof(double), HugePageMinimumBytes);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(factor->x) % HugePage, 0u);
  if (systemOffersHugePages())
  {
    EXPECT_TRUE(advisedForHugePages(factor->x)) << mappingFlags(factor->x);
  }
  // The factor is the matrix's: A x = b solved with it leaves a residual at rounding.
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(lower.rows(), -1.0, 1.0);
  cholmod_dense rhs{};
  rhs.nrow = rhs.nzmax = rhs.d = static_cast<std::size_t>(b.size());
  rhs.ncol = 1;
  rhs.x = b.data();
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor, &rhs, &common);
  ASSERT_NE(x, nullptr);
  const Eigen::Map<const Eigen::VectorXd> solution(static_cast<const double*>(x->x), b.size());
  const Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
  EXPECT_LT((full * solution - b).norm() / b.norm(), 1e-10);
  cholmod_free_dense(&x, &common);
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
}

namespace
{
using SuiteSparseAllocator = void* (*)(std::size_t);

void* otherMalloc(std::size_t bytes)
{
  return std::malloc(bytes);
}

SuiteSparseAllocator currentMalloc()
{
#if SUITESPARSE_MAIN_VERSION >= 7
  return SuiteSparse_config_malloc_func_get();
#else
  return SuiteSparse_config.malloc_func;
#endif
}

void setMalloc(SuiteSparseAllocator allocator)
{
#if SUITESPARSE_MAIN_VERSION >= 7
  SuiteSparse_config_malloc_func_set(allocator);
#else
  SuiteSparse_config.malloc_func = allocator;
#endif
}
} // namespace

TEST(HugePages, CHOLMODAllocatorScopesNestAcrossThreadsAndLeaveAnotherAllocatorAlone)
{
  ASSERT_EQ(currentMalloc(), &std::malloc);
  {
    const CholmodAllocatorScope outer;
    EXPECT_TRUE(cholmodAllocatorInstalled());
    {
      const CholmodAllocatorScope inner;
      EXPECT_TRUE(cholmodAllocatorInstalled());
    }
    EXPECT_TRUE(cholmodAllocatorInstalled()) << "the inner scope's end keeps the outer's allocator";
    // A scope on another thread that ends first leaves this one's allocator installed.
    std::thread([] { const CholmodAllocatorScope other; }).join();
    EXPECT_TRUE(cholmodAllocatorInstalled());
  }
  EXPECT_EQ(currentMalloc(), &std::malloc);
  // Scopes on two threads, ended in the other order than begun: malloc is back after the last.
  {
    std::mutex mutex;
    std::condition_variable changed;
    int stage = 0;
    std::thread second([&] {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait(lock, [&] { return stage == 1; });
      {
        const CholmodAllocatorScope scope;
        stage = 2;
        changed.notify_all();
        changed.wait(lock, [&] { return stage == 3; });
      }
      stage = 4;
      changed.notify_all();
    });
    {
      std::unique_lock<std::mutex> lock(mutex);
      auto first = std::make_unique<CholmodAllocatorScope>();
      stage = 1;
      changed.notify_all();
      changed.wait(lock, [&] { return stage == 2; });
      first.reset(); // the first scope ends while the second is alive
      EXPECT_TRUE(cholmodAllocatorInstalled());
      stage = 3;
      changed.notify_all();
      changed.wait(lock, [&] { return stage == 4; });
    }
    second.join();
  }
  EXPECT_EQ(currentMalloc(), &std::malloc);
  // Another allocator, set by another SuiteSparse user, is neither replaced nor reset.
  setMalloc(&otherMalloc);
  {
    const CholmodAllocatorScope scope;
    EXPECT_FALSE(cholmodAllocatorInstalled());
    EXPECT_EQ(currentMalloc(), &otherMalloc);
  }
  EXPECT_EQ(currentMalloc(), &otherMalloc);
  setMalloc(&std::malloc);
}
#endif
