// The benchmark's worker processes: fork, one pipe per worker, rows read with poll as they arrive, waitpid.
#include "KerfBenchmarkWorkers.h"

#include "Error.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

namespace kerf
{

std::vector<BenchmarkRow> runInWorkers(const std::vector<int>& models, int jobs,
  const std::function<BenchmarkRow(int)>& work, const std::function<void(std::size_t, const BenchmarkRow&)>& finished)
{
  std::vector<BenchmarkRow> rows;
  if (jobs <= 1)
  {
    for (int model : models)
    {
      rows.push_back(work(model));
      finished(rows.size(), rows.back());
    }
    return rows;
  }
  struct Worker
  {
    pid_t pid;
    int fd;
    std::string buffer;
  };
  std::vector<Worker> workers;
  std::fflush(nullptr);
  for (int w = 0; w < jobs; ++w)
  {
    int fds[2];
    if (pipe(fds) != 0)
    {
      throw Error("cannot create a pipe for the workers");
    }
    const pid_t pid = fork();
    if (pid < 0)
    {
      throw Error("cannot start a worker process");
    }
    if (pid == 0)
    {
      close(fds[0]);
      int status = 0;
      for (std::size_t i = static_cast<std::size_t>(w); i < models.size(); i += static_cast<std::size_t>(jobs))
      {
        std::string line;
        try
        {
          line = formatResultRow(work(models[i])) + "\n";
        }
        catch (const std::exception& e)
        {
          line = "!" + std::string(e.what()) + "\n";
          status = 1;
        }
        if (write(fds[1], line.data(), line.size()) != static_cast<ssize_t>(line.size()))
        {
          status = 1;
        }
      }
      close(fds[1]);
      std::fflush(nullptr);
      _exit(status);
    }
    close(fds[1]);
    workers.push_back({ pid, fds[0], "" });
  }
  std::vector<std::string> failures;
  std::size_t open = workers.size();
  while (open > 0)
  {
    std::vector<pollfd> fds;
    for (const Worker& w : workers)
    {
      fds.push_back({ w.fd, POLLIN, 0 });
    }
    if (poll(fds.data(), fds.size(), -1) < 0)
    {
      continue;
    }
    for (std::size_t i = 0; i < workers.size(); ++i)
    {
      if (workers[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP)))
      {
        continue;
      }
      char chunk[4096];
      const ssize_t n = read(workers[i].fd, chunk, sizeof(chunk));
      if (n <= 0)
      {
        close(workers[i].fd);
        workers[i].fd = -1;
        --open;
        continue;
      }
      workers[i].buffer.append(chunk, static_cast<std::size_t>(n));
      std::size_t end;
      while ((end = workers[i].buffer.find('\n')) != std::string::npos)
      {
        const std::string line = workers[i].buffer.substr(0, end);
        workers[i].buffer.erase(0, end + 1);
        if (!line.empty() && line[0] == '!')
        {
          failures.push_back(line.substr(1));
          continue;
        }
        rows.push_back(parseResultRow(line));
        finished(rows.size(), rows.back());
      }
    }
  }
  for (const Worker& w : workers)
  {
    int status = 0;
    waitpid(w.pid, &status, 0);
    if (failures.empty() && !(WIFEXITED(status) && WEXITSTATUS(status) == 0))
    {
      failures.push_back("a worker process ended abnormally");
    }
  }
  if (!failures.empty())
  {
    throw Error(failures.size() == 1 ? failures[0]
                                     : std::to_string(failures.size()) + " models failed; the first: " + failures[0]);
  }
  std::sort(rows.begin(), rows.end(), [](const BenchmarkRow& a, const BenchmarkRow& b) { return a.model < b.model; });
  return rows;
}

} // namespace kerf
