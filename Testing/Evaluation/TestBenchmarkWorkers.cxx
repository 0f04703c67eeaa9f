// kerf::runInWorkers: the same rows in model order whatever the number of worker processes, the
// progress callback once per model, and failures (an exception, a worker that dies) as kerf::Error.
#include "KerfBenchmarkWorkers.h"

#include "Error.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <string>
#include <vector>

using namespace kerf;

namespace
{
// A row whose values depend only on the model, in two of results.csv's columns.
BenchmarkRow rowOf(int model)
{
  BenchmarkRow row;
  row.model = model;
  row.category = model % 2 ? "Odd" : "Even";
  row.method = "test";
  row.parameters = "k=" + std::to_string(model % 3);
  row.values["RandIndexError"] = 1.0 / (model + 3);
  row.values["Segments"] = model % 5;
  return row;
}

std::vector<BenchmarkRow> run(const std::vector<int>& models, int jobs, std::vector<std::size_t>* done = nullptr)
{
  return runInWorkers(models, jobs, rowOf, [done](std::size_t count, const BenchmarkRow&) {
    if (done)
    {
      done->push_back(count);
    }
  });
}
} // namespace

TEST(BenchmarkWorkers, RowsInModelOrderWhateverTheNumberOfWorkers)
{
  const std::vector<int> models = { 12, 3, 7, 1, 20, 5, 9 };
  std::vector<std::size_t> done;
  const std::vector<BenchmarkRow> alone = run(models, 1, &done);
  ASSERT_EQ(alone.size(), models.size());
  EXPECT_EQ(done, (std::vector<std::size_t>{ 1, 2, 3, 4, 5, 6, 7 }));
  for (int jobs : { 2, 3, 8 })
  {
    done.clear();
    const std::vector<BenchmarkRow> rows = run(models, jobs, &done);
    ASSERT_EQ(rows.size(), models.size()) << jobs << " workers";
    EXPECT_EQ(done, (std::vector<std::size_t>{ 1, 2, 3, 4, 5, 6, 7 })) << jobs << " workers";
    std::vector<int> order;
    for (const BenchmarkRow& row : rows)
    {
      order.push_back(row.model);
    }
    EXPECT_EQ(order, (std::vector<int>{ 1, 3, 5, 7, 9, 12, 20 })) << jobs << " workers";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      const BenchmarkRow expected = rowOf(rows[i].model);
      EXPECT_EQ(rows[i].category, expected.category);
      EXPECT_EQ(rows[i].parameters, expected.parameters);
      EXPECT_EQ(rows[i].values.at("Segments"), expected.values.at("Segments"));
      // results.csv keeps 10 significant digits.
      EXPECT_NEAR(rows[i].values.at("RandIndexError"), expected.values.at("RandIndexError"), 1e-10);
    }
  }
  // In this process (one job) the rows come in the order given; the workers' are sorted.
  EXPECT_EQ(alone.front().model, 12);
  EXPECT_TRUE(run({}, 3).empty());
}

TEST(BenchmarkWorkers, AFailingModelIsReportedWithItsMessage)
{
  auto failing = [](int model) {
    if (model == 4)
    {
      throw Error("model 4 has no human segmentation");
    }
    return rowOf(model);
  };
  auto ignore = [](std::size_t, const BenchmarkRow&) {};
  for (int jobs : { 1, 2 })
  {
    try
    {
      runInWorkers({ 1, 2, 3, 4, 5 }, jobs, failing, ignore);
      ADD_FAILURE() << "no error with " << jobs << " workers";
    }
    catch (const Error& e)
    {
      EXPECT_STREQ(e.what(), "model 4 has no human segmentation") << jobs << " workers";
    }
  }
  auto twoFail = [](int model) {
    if (model % 2 == 0)
    {
      throw Error("model " + std::to_string(model) + " failed");
    }
    return rowOf(model);
  };
  try
  {
    runInWorkers({ 1, 2, 3, 4, 5 }, 2, twoFail, ignore);
    ADD_FAILURE() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("2 models failed; the first: model ", 0), 0u) << e.what();
  }
}

TEST(BenchmarkWorkers, AWorkerThatDiesIsAnError)
{
  auto dying = [](int model) {
    if (model == 2)
    {
      _exit(7); // in the worker process only
    }
    return rowOf(model);
  };
  try
  {
    runInWorkers({ 1, 2, 3, 4 }, 2, dying, [](std::size_t, const BenchmarkRow&) {});
    ADD_FAILURE() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_STREQ(e.what(), "a worker process ended abnormally");
  }
}
