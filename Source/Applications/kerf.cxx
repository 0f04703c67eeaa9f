// kerf: the command-line program that runs Kerf's filters on mesh files and renders the results.
#include "KerfCommands.h"

#include "Threads.h"

#include "vtkSegmentationBenchmark.h"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const char* const Version = "0.1.0";

struct Command
{
  const char* name;
  const char* usage;
  const char* help;
};

const Command Commands[] = {
  { "showcase", "kerf showcase [MESH] [--stroke FILE] [-o FOLDER]",
    "The showcase pipeline: cuts MESH (default: the bundled camel) along a stroke (default:\n"
    "<mesh>-neck-stroke.vtk beside the mesh): surface descriptors, stroke constraints, harmonic\n"
    "field, the isoline nearest the stroke and the segments it bounds. Writes the surface with\n"
    "every computed array (.vtp), the cut curve (.vtp) and a picture (.png) into FOLDER\n"
    "(default: kerf-output), then prints a summary." },
  { "cut", "kerf cut MESH --stroke FILE [-o OUT.vtp] [--curve CURVE.vtp] [--png OUT.png] [cut options]",
    "Cuts MESH along the isoline of a harmonic field built from a stroke (SeamCut): the stroke\n"
    "becomes +1/-1 constraints on both sides, the field is solved, and the isoline nearest the\n"
    "stroke splits the mesh into segments (cell array Segment).\n"
    "Cut options: --weighting uniform|cotangent|concavity|smooth-concavity (cotangent),\n"
    "--iso-value I (0), --samples N per stroke segment (4), --offset F of the diagonal (0.005, at most\n"
    "5% of a stroke's length), --soft-weight W (1), --formulation auto|least-squares|point-values\n"
    "(auto: point values where the mean edge is at most 1/180 of the diagonal, else least squares).\n"
    "--timings prints the time of each step (reading, each stage, writing)." },
  { "unwrap",
    "kerf unwrap MESH --curves CURVES [-o OUT.obj] [--png OUT.png] [--seams N] [--mode M] [--margin F]\n"
    "            [--method lscm|linabf] [--checker N] [--refuse-non-disks]",
    "Cuts MESH open along curves on it (cuts from kerf cut or kerf showcase, seams; points on the\n"
    "surface) and gives every chart texture coordinates (a UV atlas): the curves become mesh edges\n"
    "(--mode scissor|snap|inverse-snap, default scissor: triangles split along the exact curves),\n"
    "the charts they bound are flattened (--method lscm, least-squares conformal maps, the default\n"
    "and the faster; or linabf, linear angle based flattening, less distortion on strongly curved\n"
    "charts at about twice the time) and packed into the unit square (--margin F of its side\n"
    "between charts, default 0.01). A chart that is not a disk (closed, several boundary loops,\n"
    "handles) is cut into one along short paths, or refused with --refuse-non-disks. --seams N\n"
    "adds up to N seams to each chart where its map is worst (from the tip of a protrusion to the\n"
    "border), until its L2 stretch is 1.2 (default 10; 0 for none).\n"
    "Writes the cut mesh with its texture coordinates (-o; OBJ as vt, also .ply .vtp .vtk) and/or a\n"
    "picture (--png): the mesh with a checkerboard texture of N squares per side (--checker,\n"
    "default 24) beside the UV layout coloured by stretch; prints the charts' stretch, shear,\n"
    "flipped triangles and overlaps." },
  { "descriptors", "kerf descriptors MESH [-o OUT.vtp] [--png OUT.png] [render options]",
    "Computes the surface descriptors (normals, principal curvatures and directions, mean and\n"
    "Gaussian curvature, concavity, normal-cone angle) and writes them and/or a picture." },
  { "segment",
    "kerf segment MESH [--method NAME] [-k N | --auto] [-o OUT.vtp] [--seg OUT.seg] [--png OUT.png] [render options]\n"
    "       kerf segment FOLDER [--method NAME] [-k N | --auto] [-o OUT_FOLDER] [--quiet]\n"
    "       mpirun -np N kerf segment FOLDER [...]",
    "Segments a mesh automatically into k parts (-k, default the filter's: 6 for the ensemble; with\n"
    "--auto the ensemble chooses k among 5 to 11, at about seven times the time) and writes the\n"
    "mesh with its Segment cell array (-o, any format convert writes), the labels as a\n"
    ".seg file (one per triangle, the Princeton benchmark's format) and/or a picture. Given a\n"
    "folder, segments each mesh file in it (by name) into OUT_FOLDER/NAME.vtp and NAME.seg\n"
    "(default folder kerf-segment), a progress line each (none with --quiet), and a line per\n"
    "mesh in OUT_FOLDER/summary.csv (triangles, segments, milliseconds, rank, error); a mesh\n"
    "that fails is reported, the others go on, and the exit code is 1. Under mpirun the meshes\n"
    "are dealt out over the ranks (the largest first, each to the rank with the fewest bytes so\n"
    "far), with the same files as a run without it. Methods (each the filter of that name with\n"
    "its defaults; the first is the default):" },
  { "info", "kerf info MESH",
    "Prints the mesh size and whether Kerf's filters accept it (and if not, why). Exit code 1\n"
    "when the surface is refused." },
  { "convert", "kerf convert IN OUT", "Converts between mesh formats (by extension)." },
  { "render", "kerf render MESH -o OUT.png [render options]",
    "Renders a mesh, coloured by a point or cell array, to a PNG." },
  { "benchmark", "kerf benchmark --data FOLDER [--method NAME] [--parameters P] [--models 1,9] [--jobs N] [-o FOLDER]",
    "Runs a segmentation method over a folder in the Princeton benchmark's layout (off/N.off,\n"
    "seg/N/N_j.seg, nSeg-ByModel.txt) and scores it against the human segmentations. Writes\n"
    "results.csv (one row per model: model, category, method, parameters, every metric, time),\n"
    "summary.csv (means per category and overall) and pictures/N.png (the method's segmentation\n"
    "beside a human's) into the output folder (default: kerf-benchmark). --jobs N runs N\n"
    "processes; --no-pictures skips the pictures (which need a display: xvfb-run -a). Methods:" },
};

void printHelp()
{
  std::cout << "kerf " << Version << ": mesh segmentation with VTK\n\n"
            << "Usage: kerf COMMAND [ARGUMENTS] [OPTIONS]\n\nCommands:\n";
  for (const Command& c : Commands)
  {
    std::cout << "  " << std::left << std::setw(12) << c.name << c.usage << "\n";
  }
  std::cout << "\nMesh files: .off .ply .obj .stl .vtp .vtk (read); .vtp .vtk .ply .obj .stl .off (write).\n"
            << "\nRender options:\n"
            << "  --array NAME          colour by this point or cell array\n"
            << "  --map diverging|sequential|categorical   colour map (default diverging)\n"
            << "  --directions NAME     draw this 3-component point array as strokes\n"
            << "  --range-fraction F    colour range covers this fraction of the values (0.95)\n"
            << "  --size WxH            image size in pixels (900x700)\n"
            << "  --azimuth DEG --elevation DEG   camera rotation (30, 20)\n"
            << "  --caption TEXT        caption in the top-left corner\n"
            << "\nOther options: -o FILE (output), --quiet, -h/--help (also after a command),\n"
            << "--threads N (the most threads Kerf uses; default 0: KERF_NUM_THREADS, else every core).\n"
            << "Rendering needs a display; on a headless machine run under xvfb-run -a.\n";
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" || std::string(argv[1]) == "help")
  {
    printHelp();
    return argc < 2 ? 2 : 0;
  }
  if (std::string(argv[1]) == "--version")
  {
    std::cout << "kerf " << Version << "\n";
    return 0;
  }
  const std::string name = argv[1];
  try
  {
    const kerf::Arguments args = kerf::parseArguments(argc, argv, 2);
    if (args.has("threads"))
    {
      kerf::setThreadLimit(args.integer("threads", 0, 0, 1024));
    }
    for (const Command& c : Commands)
    {
      if (name != c.name)
      {
        continue;
      }
      if (args.has("help"))
      {
        std::cout << "Usage: " << c.usage << "\n\n" << c.help << "\n";
        if (name == "segment")
        {
          std::cout << "  " << kerf::SegmentMethodNames() << "\n";
        }
        if (name == "benchmark")
        {
          const std::vector<std::string> methods = vtkSegmentationBenchmark::GetMethodNames();
          std::size_t width = 0;
          for (const std::string& method : methods)
          {
            width = std::max(width, method.size() + 2);
          }
          for (const std::string& method : methods)
          {
            std::cout << "  " << std::left << std::setw(static_cast<int>(width)) << method
                      << vtkSegmentationBenchmark::GetMethodDescription(method) << "\n";
          }
        }
        return 0;
      }
      if (name == "showcase")
      {
        return kerf::RunShowcase(args, argv[0]);
      }
      if (name == "descriptors")
      {
        return kerf::RunDescriptors(args);
      }
      if (name == "segment")
      {
        return kerf::RunSegment(args);
      }
      if (name == "info")
      {
        return kerf::RunInfo(args);
      }
      if (name == "benchmark")
      {
        return kerf::RunBenchmark(args);
      }
      if (name == "cut")
      {
        return kerf::RunCut(args);
      }
      if (name == "unwrap")
      {
        return kerf::RunUnwrap(args);
      }
      if (name == "convert")
      {
        return kerf::RunConvert(args);
      }
      return kerf::RunRender(args);
    }
    throw kerf::CommandError{ "unknown command '" + name + "' (see kerf --help)" };
  }
  catch (const kerf::CommandError& e)
  {
    // One write for the whole line (std::cerr writes each << at once), so that under mpirun the
    // launcher's own messages cannot land inside it.
    const std::string line = "kerf: error: " + e.message + "\n";
    std::cerr.write(line.data(), static_cast<std::streamsize>(line.size()));
    std::cerr.flush();
    return 1;
  }
}
