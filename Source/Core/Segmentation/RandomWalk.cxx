// Multi-label random walks: one harmonic field per label, the largest probability kept per vertex and face.
#include "Segmentation/RandomWalk.h"

#include "Error.h"
#include "Harmonic/HarmonicFieldSolver.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace kerf
{

RandomWalkLabelling randomWalkLabels(const TriangleMesh& mesh, const std::vector<double>& edgeWeights,
  const std::vector<int>& seedVertices, const std::vector<int>& seedLabels)
{
  const int n = mesh.vertexCount();
  if (seedVertices.size() != seedLabels.size())
  {
    throw Error("the random walks have " + std::to_string(seedVertices.size()) + " seed vertices but " +
      std::to_string(seedLabels.size()) + " labels");
  }
  if (seedVertices.empty())
  {
    throw Error("the random walks need at least one seed");
  }
  if (static_cast<int>(edgeWeights.size()) != mesh.edgeCount())
  {
    throw Error("the random walks' edge weights do not belong to this mesh");
  }
  for (const double weight : edgeWeights)
  {
    if (!(weight >= 0.0 && std::isfinite(weight)))
    {
      throw Error("the random walks' edge weights must be finite and not negative");
    }
  }
  // A vertex's seed label, -1 if it is no seed.
  std::vector<int> seedLabel(static_cast<std::size_t>(n), -1);
  std::vector<char> seededComponent(static_cast<std::size_t>(mesh.componentCount()), 0);
  for (std::size_t i = 0; i < seedVertices.size(); ++i)
  {
    const int v = seedVertices[i];
    if (v < 0 || v >= n || mesh.vertexComponent(v) < 0)
    {
      throw Error("random-walk seed " + std::to_string(v) + " is not a vertex of the mesh's triangles");
    }
    if (seedLabels[i] < 0)
    {
      throw Error("random-walk seed " + std::to_string(v) + " has the negative label " + std::to_string(seedLabels[i]));
    }
    if (seedLabel[v] >= 0 && seedLabel[v] != seedLabels[i])
    {
      throw Error("random-walk seed " + std::to_string(v) + " is given two labels");
    }
    seedLabel[v] = seedLabels[i];
    seededComponent[mesh.vertexComponent(v)] = 1;
  }
  RandomWalkLabelling result;
  result.labels = seedLabels;
  std::sort(result.labels.begin(), result.labels.end());
  result.labels.erase(std::unique(result.labels.begin(), result.labels.end()), result.labels.end());

  // The hard set: the seeds, and every vertex of a component without seeds (held at 0).
  FieldConstraints constraints;
  for (int v = 0; v < n; ++v)
  {
    const int component = mesh.vertexComponent(v);
    if (seedLabel[v] >= 0 || (component >= 0 && !seededComponent[component]))
    {
      constraints.dirichletVertices.push_back(v);
    }
  }
  constraints.dirichletValues.assign(constraints.dirichletVertices.size(), 0.0);

  result.vertexLabels.assign(static_cast<std::size_t>(n), -1);
  result.vertexProbabilities.assign(static_cast<std::size_t>(n), 0.0);
  result.secondLabels.assign(static_cast<std::size_t>(n), -1);
  result.secondProbabilities.assign(static_cast<std::size_t>(n), 0.0);
  result.faceLabels.assign(static_cast<std::size_t>(mesh.faceCount()), -1);
  std::vector<double> faceBest(static_cast<std::size_t>(mesh.faceCount()), -1.0);
  HarmonicFieldSolver solver;
  for (const int label : result.labels)
  {
    for (std::size_t i = 0; i < constraints.dirichletVertices.size(); ++i)
    {
      constraints.dirichletValues[i] = seedLabel[constraints.dirichletVertices[i]] == label ? 1.0 : 0.0;
    }
    // The same hard set every time: the first label factors, the others back-substitute.
    std::vector<double> field = solver.solve(mesh, edgeWeights, constraints).field;
    for (double& value : field)
    {
      value = std::min(1.0, std::max(0.0, value)); // the maximum principle, up to rounding
    }
    for (int v = 0; v < n; ++v)
    {
      const int component = mesh.vertexComponent(v);
      if (component < 0 || !seededComponent[component])
      {
        continue;
      }
      const double p = field[v];
      if (result.vertexLabels[v] < 0 || p > result.vertexProbabilities[v])
      {
        result.secondLabels[v] = result.vertexLabels[v];
        result.secondProbabilities[v] = result.vertexProbabilities[v];
        result.vertexLabels[v] = label;
        result.vertexProbabilities[v] = p;
      }
      else if (result.secondLabels[v] < 0 || p > result.secondProbabilities[v])
      {
        result.secondLabels[v] = label;
        result.secondProbabilities[v] = p;
      }
    }
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      const Triangle& t = mesh.triangle(f);
      if (!seededComponent[mesh.vertexComponent(t[0])])
      {
        continue;
      }
      const double sum = field[t[0]] + field[t[1]] + field[t[2]];
      if (sum > faceBest[f])
      {
        faceBest[f] = sum;
        result.faceLabels[f] = label;
      }
    }
  }
  return result;
}

SpineWalk walkFromSpines(const TriangleMesh& mesh, const std::vector<double>& edgeWeights,
  const std::vector<SegmentSpine>& spines, const std::vector<int>& faceLabels)
{
  if (static_cast<int>(faceLabels.size()) != mesh.faceCount())
  {
    throw Error("the segmentation walked from its spines does not belong to this mesh");
  }
  SpineWalk walk;
  walk.faceLabels = faceLabels;
  int labelCount = 0;
  for (const SegmentSpine& spine : spines)
  {
    if (spine.label < 0)
    {
      throw Error("a spine has the negative label " + std::to_string(spine.label));
    }
    for (const int f : spine.faces)
    {
      if (f < 0 || f >= mesh.faceCount() || faceLabels[f] != spine.label)
      {
        throw Error("a spine of label " + std::to_string(spine.label) + " passes through face " + std::to_string(f) +
          ", which is not one of that segment's faces");
      }
    }
    labelCount = std::max(labelCount, spine.label + 1);
  }
  // Every segment needs a spine, or the walks could take all of its faces.
  std::vector<char> hasSpine(static_cast<std::size_t>(labelCount), 0);
  for (const SegmentSpine& spine : spines)
  {
    hasSpine[spine.label] = 1;
  }
  for (const int label : faceLabels)
  {
    if (label >= 0 && (label >= labelCount || !hasSpine[label]))
    {
      return walk;
    }
  }
  std::vector<int> seedLabel(static_cast<std::size_t>(mesh.vertexCount()), -1);
  const int shared = -2;
  for (const SegmentSpine& spine : spines)
  {
    for (const int f : spine.faces)
    {
      for (const int v : mesh.triangle(f))
      {
        seedLabel[v] = seedLabel[v] == -1 || seedLabel[v] == spine.label ? spine.label : shared;
      }
    }
  }
  std::vector<int> vertices, labels;
  std::vector<char> seeded(static_cast<std::size_t>(labelCount), 0);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (seedLabel[v] >= 0)
    {
      vertices.push_back(v);
      labels.push_back(seedLabel[v]);
      seeded[seedLabel[v]] = 1;
    }
  }
  for (const SegmentSpine& spine : spines)
  {
    if (!seeded[spine.label])
    {
      return walk;
    }
  }
  if (vertices.empty())
  {
    return walk; // no segment, so no spine
  }
  const std::vector<int> walked = randomWalkLabels(mesh, edgeWeights, vertices, labels).faceLabels;
  std::vector<char> won(seeded.size(), 0);
  for (const int label : walked)
  {
    if (label >= 0)
    {
      won[label] = 1;
    }
  }
  for (const SegmentSpine& spine : spines)
  {
    if (!won[spine.label])
    {
      return walk;
    }
  }
  for (std::size_t f = 0; f < walked.size(); ++f)
  {
    walk.changedFaces += walked[f] != faceLabels[f] ? 1 : 0;
  }
  walk.faceLabels = walked;
  walk.applied = true;
  return walk;
}

} // namespace kerf
