// SPDX-License-Identifier: GPL-3.0-or-later
// medial-axis: the Structural MAT of a closed triangle surface from the
// command line. See PrintHelp() for the options and exit codes.
#include "HeapTuning.h"
#include "Mesh/MedialMesh.h"
#include "Mesh/MedialMeshQuality.h"
#include "Mesh/MedialSheets.h"
#include "Screenshot.h"
#include "Structure/MedialStructure.h"
#include "Surface/SharpEdgeContent.h"
#include "ToolSupport.h"
#include "UdfCommand.h"
#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkErrorEventText.h"
#include "vtkFilletDetector.h"
#include "vtkMedialAxisWriter.h"
#include "vtkMedialMeshConversion.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialSkeletalDiagram.h"
#include "vtkMedialStructure.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkMidSurfaceExtractor.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfaceFileReader.h"
#include "vtkSurfacePreparation.h"

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace medialaxis::tool;

enum ExitCode
{
  Ok = 0,
  BadArguments = 2,
  BadInput = 3,
  ComputationFailed = 4
};

void PrintHelp()
{
  std::cout <<
    R"(Usage: medial-axis [options] INPUT OUTPUT_DIR
       medial-axis --udf [--epsilon E] [--snap] FIELD OUTPUT_DIR

Computes the Structural Medial Axis Transform of the closed triangle surface
INPUT (OBJ, OFF, PLY, STL, VTP or VTK) or, with --udf, the surface of an
unsigned distance field (the medial axis of its epsilon-shell), and writes
into OUTPUT_DIR:
  mat.ma, mat.vtp       the simplified medial mesh (spheres: points with point
                        data Radius; slabs: triangles; cones: lines)
and, on request, the files below.

Options:
  --preset cad|organic  the paper's settings: cad = 50,000 samples, 5,000
                        spheres, sharp features preserved; organic (default)
                        = 10,000 samples, 1,000 spheres; auto = cad when
                        the surface's sharp edges form creases at least
                        1.5 times the square root of its area long (a box
                        face's rim; filtered normals, so scan noise does not
                        count), else organic; the report gives the choice
  --samples N           surface samples (overrides the preset)
  --adaptive, --uniform sample thin parts (tentacles, ears, thin plates)
                        densely, by the local thickness, or the whole surface
                        uniformly (default: adaptive with the organic preset,
                        uniform with cad)
  --target N            spheres left after simplification (overrides the preset)
  --max-error E         instead of --target: the fewest spheres whose two-sided
                        Hausdorff distance to the surface stays within E of the
                        bounding-box diagonal, as a fraction (0.005) or a
                        percentage (0.5%); by error-bounded collapses (one to
                        four runs), else a search of about ten simplify-and-
                        measure runs; reached count and distance in the report
  --sharp, --no-sharp   snap spheres onto sharp convex edges (CAD) or not
  --feature-angle DEG   dihedral tolerance for sharp edges (default 45)
  --feature-filtering N iterations of bilateral normal filtering that must
                        confirm every sharp convex edge, so that noise does
                        not pass for ridges (default 3; 0 = raw normals only)
  --strategy structural|qmat
                        simplifier: structural (default, Structural MAT's
                        Atlas energy) or qmat (Q-MAT's slab quadric error on
                        the same initial medial mesh, for comparison)
  --fringe-collapses, --no-fringe-collapses
                        let the simplifier break the link condition with
                        collapses that keep the Euler characteristic, or not:
                        they remove the fringe of thin fins along large
                        fillets and keep organic shapes simplified far (e.g.
                        50,000 samples -> 1,000 spheres) from losing ears and
                        fingers (default: on without --sharp when the target
                        is at least 200 spheres; below 200 without --sharp,
                        both are run and the one closer to the surface is
                        kept: on for most organic shapes, off for tubes and
                        blobs, whose medial axis is a curve or a point; off
                        with --sharp)
  --hair-angle DEG      cleaner or closer: Voronoi faces whose two surface
                        samples subtend less than DEG at their spheres stand
                        for the sampling, not the thickness, and are eroded
                        before simplification, keeping the topology
                        (default 45; larger: fewer, larger sheets; 0: off;
                        without --sharp, as --fin-budget and --pleat-angle)
  --pleat-angle DEG     no collapse nor the final fit may add pairs of
                        triangles meeting below DEG (default 90; 10 only
                        refuses folded triangles)
  --fin-budget F        fins (small sheets that branch off a larger one over
                        a small bump of the surface) whose spheres reach out
                        of their junction by at most F of the diagonal, as a
                        fraction or a percentage, are collapsed into the
                        sheet they hang on (default 0.5%; 0 keeps them)
  --error-bands, --no-error-bands
                        take the collapses in the paper's cost order within
                        bands of local error (closer to the surface for the
                        same number of spheres, with more spike edges), or
                        not (default: on without --sharp)
  --spike-collapses     the same for spike edges only: removes most spike
                        triangles of organic shapes
  --absorb-spikes       collapse spike edges into their larger ball first:
                        far fewer spikes (organic 10,000 -> 1,000: at most
                        0.32% of the edges instead of 0.53%), slightly
                        farther (median 0.53% -> 0.55%) (default: off)
  --clamp-radii         keep every merged sphere within the nearest surface
                        sample it stands for: closer on CAD parts (median
                        Hausdorff 0.58% -> 0.47% on 13 parts), farther on
                        some organic shapes (default: off)
  --fit, --no-fit       after simplification, fit the spheres' centres and
                        radii to the surface, connectivity fixed (default:
                        on; structural strategy only)
  --spike-repair W      weight of the fit's pull on spike edges (one ball
                        nearly inside the other) until they are none
                        (default 10; 0 = leave them): organic 10,000 ->
                        1,000, largest share of spike edges 1.22% -> 0.29%
  --fit-boundary-radii, --fixed-boundary-radii
                        with --sharp, let the fit change the radii of the
                        spheres on the sheets' boundary (fillet centre lines)
                        too, or not: closer (CAD median Hausdorff 0.57% ->
                        0.36%); the fillets are found from the radii the
                        collapses placed either way (default: fitted)
  --no-repair           refuse a surface whose shells cross or that passes
                        through itself, instead of resolving the crossings
                        into the closed outer boundary of the solid (the
                        default; the report and a line say what was removed;
                        correspondence.vtp then has InputTriangleId)
  --seed S              sampler seed; same seed, same result (default 0)
  --threads T           threads for the parallel stages (0 = all, default)
  --envelope            also write envelope.vtp: the union of the medial
                        primitives (spheres, cones, slabs) as triangles
  --correspondence      also write correspondence.vtp: the surface cut into
                        the sites' cells with MedialVertexId per cell
  --fillets             find the fillets (CAD parts: use --preset cad) and
                        write fillets.vtp (one centre line per fillet, point
                        data Radius) and fillet_faces.vtp (the surface with
                        cell data FilletId, -1 off fillets); the report lists
                        each fillet's radius and length
  --structure           type every sphere (sheet, seam, junction, rim, feature,
                        fillet with --fillets, curve, isolated) and number the
                        sheets and seams: write structure.vtp (the MAT with
                        point data MedialType and TangentComponents, cell data
                        SheetId) and seams.vtp (seam edges with SeamId); the
                        report counts them
  --mid-surface         thin-walled parts: write mid_surface.vtp, the walls'
                        mid-surface (pruned, centred between the sides,
                        stitched where walls meet, extended to the lateral
                        faces) with point data Thickness and cell data
                        WallId; the report gives the walls and the wall
                        thickness
  --skeletal-diagram N  a Medial Skeletal Diagram of at most N elements from
                        the MAT: write skeleton.vtp (its vertices, edges and
                        triangles) and primitives.vtp (a generalized
                        primitive, a radius per direction, per element; cell
                        data ElementType and ElementId) until the surface is
                        within 0.5% of the diagonal of them, and
                        reconstruction.vtp (their union as one closed
                        surface); the report gives the counts and the error
                        reached (with --error also the reconstruction's
                        two-sided distances)
  --error               measure the two-sided Hausdorff distance between the
                        surface and the envelope (% of the bounding-box
                        diagonal) and write distance.vtp (the surface with
                        point data Distance)
  --screenshot FILE     render the result offscreen into a PNG: the surface
                        (semi-transparent, fillet faces coloured with
                        --fillets), the MAT coloured by radius (with
                        --mid-surface the mid-surface by thickness instead)
                        and the fillet centre lines; without an X display the tool runs
                        itself under xvfb-run (Debian package xvfb)
  --report FILE         write a JSON report: parameters, per-stage times, peak
                        memory, counts, Euler characteristic, triangle quality
                        and (with --error) the Hausdorff distances
  --quiet               no progress bar (it is shown only on a terminal)
  --udf                 INPUT is an unsigned distance field, not a surface:
                        .vti or legacy .vtk image data (point data: the
                        distance; --array NAME picks the array) or a 3-D
                        float .npy array a[i, j, k] (x along i) with
                        --spacing S [--origin X Y Z]; writes surface.vtp
                        (the extracted surface, open boundaries and
                        junctions kept; point data ShellRadius) and
                        shell.vtp (the epsilon-shell), and with --report the
                        counts (boundary loops, junction edges) and times
  --epsilon E           with --udf: the shell's distance from the surface
                        (default: twice the grid spacing; at least the
                        spacing)
  --snap                with --udf: project the points onto the field's zero
                        set
  -h, --help            this text

Environment: the tool starts itself again with glibc's heap tuned for large
blocks (GLIBC_TUNABLES: blocks up to 32 MB kept in the heap, freed memory
kept, transparent huge pages), a third faster where page faults are dear
(virtual machines); MEDIALAXIS_TUNE_HEAP=0 turns that off, and tunables of
your own in GLIBC_TUNABLES (glibc.malloc.*) are left as they are.

Exit codes: 0 done; 2 bad arguments; 3 unreadable or invalid input (the
message names the defect, e.g. an open surface and its boundary edges);
4 the computation failed.
)";
}

struct Options
{
  std::string Input, OutputDir, Report, Screenshot;
  vtkIdType Samples = -1, Target = -1;
  int Sharp = -1;            // -1: from the preset
  int Adaptive = -1;         // -1: from the preset
  double MaximumError = 0.0; // 0: --target
  bool Cad = false, AutomaticPreset = false, Envelope = false, Correspondence = false,
       Error = false, Quiet = false, Fillets = false, Structure = false, MidSurface = false,
       SpikeCollapses = false, ClampRadii = false, AbsorbSpikes = false, QMat = false,
       FinalFit = true, FitBoundaryRadii = true, Repair = true;
  int FringeCollapses = vtkAtlasMedialAxisSimplifier::FringeAutomatic;
  int ErrorBands = vtkAtlasMedialAxisSimplifier::BandsAutomatic;
  double HairAngle = 45.0;
  double FinBudget = 0.005;
  double PleatAngle = 90.0;
  double FeatureAngle = 45.0;
  int FeatureNormalFiltering = 3;
  double SpikeRepair = 10.0;
  int Seed = 0, Threads = 0;
  int SkeletalDiagram = 0; // most elements; 0: none
  bool Udf = false;        // INPUT is an unsigned distance field
  medialaxis::tool::UdfOptions UdfRun;
};

bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0';
}

// Returns an error message, or "" when the arguments are usable.
std::string Parse(int argc, char** argv, Options& o, bool& help)
{
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](double& out) -> std::string
    {
      if (i + 1 >= argc)
      {
        return arg + " needs a value";
      }
      if (!ParseNumber(argv[++i], out))
      {
        return arg + " needs a number, got '" + argv[i] + "'";
      }
      return "";
    };
    double number = 0.0;
    std::string problem;
    if (arg == "-h" || arg == "--help")
    {
      help = true;
    }
    else if (arg == "--preset")
    {
      if (i + 1 >= argc)
      {
        return "--preset needs cad, organic or auto";
      }
      const std::string preset = argv[++i];
      if (preset != "cad" && preset != "organic" && preset != "auto")
      {
        return "--preset must be cad, organic or auto, got '" + preset + "'";
      }
      o.Cad = preset == "cad";
      o.AutomaticPreset = preset == "auto";
    }
    else if (arg == "--strategy")
    {
      if (i + 1 >= argc)
      {
        return "--strategy needs structural or qmat";
      }
      const std::string strategy = argv[++i];
      if (strategy != "structural" && strategy != "qmat")
      {
        return "--strategy must be structural or qmat, got '" + strategy + "'";
      }
      o.QMat = strategy == "qmat";
    }
    else if (arg == "--samples" || arg == "--target")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      if (!(number >= 1.0 && number <= 1e8) ||
        number != static_cast<double>(static_cast<long long>(number)))
      {
        return arg + " must be a whole number from 1 to 100000000";
      }
      (arg == "--samples" ? o.Samples : o.Target) = static_cast<vtkIdType>(number);
    }
    else if (arg == "--max-error" || arg == "--fin-budget")
    {
      if (i + 1 >= argc)
      {
        return arg + " needs a value, e.g. 0.5% or 0.005";
      }
      std::string text = argv[++i];
      const bool percent = !text.empty() && text.back() == '%';
      if (percent)
      {
        text.pop_back();
      }
      if (!ParseNumber(text.c_str(), number))
      {
        return arg + " needs a number or a percentage, got '" + std::string(argv[i]) + "'";
      }
      number = percent ? number / 100.0 : number;
      if (arg == "--fin-budget")
      {
        if (!(number >= 0.0 && number <= 0.1))
        {
          return "--fin-budget must be from 0 to 10% of the diagonal";
        }
        o.FinBudget = number;
        continue;
      }
      if (!(number > 0.0 && number <= 1.0))
      {
        return "--max-error must be above 0 and at most 100% of the diagonal";
      }
      o.MaximumError = number;
    }
    else if (arg == "--feature-angle")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      if (!(number >= 0.0 && number <= 180.0))
      {
        return "--feature-angle must be between 0 and 180 degrees";
      }
      o.FeatureAngle = number;
    }
    else if (arg == "--hair-angle" || arg == "--pleat-angle")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      const bool hair = arg == "--hair-angle";
      if (!(number >= (hair ? 0.0 : 10.0) && number <= 90.0))
      {
        return hair ? "--hair-angle must be between 0 and 90 degrees"
                    : "--pleat-angle must be between 10 and 90 degrees";
      }
      (hair ? o.HairAngle : o.PleatAngle) = number;
    }
    else if (arg == "--spike-repair")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      if (!(number >= 0.0 && number <= 1e6))
      {
        return "--spike-repair must be a weight from 0 to 1000000";
      }
      o.SpikeRepair = number;
    }
    else if (arg == "--feature-filtering")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      if (!(number >= 0.0 && number <= 100.0) ||
        number != static_cast<double>(static_cast<int>(number)))
      {
        return "--feature-filtering must be a whole number from 0 to 100";
      }
      o.FeatureNormalFiltering = static_cast<int>(number);
    }
    else if (arg == "--seed" || arg == "--threads")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      if (!(number >= 0.0 && number <= 2147483647.0))
      {
        return arg + " must be a non-negative whole number";
      }
      (arg == "--seed" ? o.Seed : o.Threads) = static_cast<int>(number);
    }
    else if (arg == "--screenshot")
    {
      if (i + 1 >= argc)
      {
        return "--screenshot needs a file name";
      }
      o.Screenshot = argv[++i];
    }
    else if (arg == "--report")
    {
      if (i + 1 >= argc)
      {
        return "--report needs a file name";
      }
      o.Report = argv[++i];
    }
    else if (arg == "--adaptive" || arg == "--uniform")
    {
      o.Adaptive = arg == "--adaptive" ? 1 : 0;
    }
    else if (arg == "--sharp" || arg == "--no-sharp")
    {
      o.Sharp = arg == "--sharp" ? 1 : 0;
    }
    else if (arg == "--envelope")
    {
      o.Envelope = true;
    }
    else if (arg == "--correspondence")
    {
      o.Correspondence = true;
    }
    else if (arg == "--fringe-collapses")
    {
      o.FringeCollapses = vtkAtlasMedialAxisSimplifier::FringeOn;
    }
    else if (arg == "--no-repair")
    {
      o.Repair = false;
    }
    else if (arg == "--no-fringe-collapses")
    {
      o.FringeCollapses = vtkAtlasMedialAxisSimplifier::FringeOff;
    }
    else if (arg == "--error-bands")
    {
      o.ErrorBands = vtkAtlasMedialAxisSimplifier::BandsOn;
    }
    else if (arg == "--no-error-bands")
    {
      o.ErrorBands = vtkAtlasMedialAxisSimplifier::BandsOff;
    }
    else if (arg == "--spike-collapses")
    {
      o.SpikeCollapses = true;
    }
    else if (arg == "--absorb-spikes")
    {
      o.AbsorbSpikes = true;
    }
    else if (arg == "--clamp-radii")
    {
      o.ClampRadii = true;
    }
    else if (arg == "--fit" || arg == "--no-fit")
    {
      o.FinalFit = arg == "--fit";
    }
    else if (arg == "--fit-boundary-radii" || arg == "--fixed-boundary-radii")
    {
      o.FitBoundaryRadii = arg == "--fit-boundary-radii";
    }
    else if (arg == "--fillets")
    {
      o.Fillets = true;
    }
    else if (arg == "--structure")
    {
      o.Structure = true;
    }
    else if (arg == "--mid-surface")
    {
      o.MidSurface = true;
    }
    else if (arg == "--skeletal-diagram")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      if (!(number >= 1.0 && number <= 1e6) ||
        number != static_cast<double>(static_cast<long long>(number)))
      {
        return arg + " must be a whole number of elements from 1 to 1000000";
      }
      o.SkeletalDiagram = static_cast<int>(number);
    }
    else if (arg == "--error")
    {
      o.Error = true;
    }
    else if (arg == "--quiet")
    {
      o.Quiet = true;
    }
    else if (arg == "--udf" || arg == "--snap")
    {
      (arg == "--udf" ? o.Udf : o.UdfRun.Snap) = true;
    }
    else if (arg == "--epsilon" || arg == "--spacing")
    {
      if (!(problem = value(number)).empty())
      {
        return problem;
      }
      if (!(number > 0.0) || !std::isfinite(number))
      {
        return arg + " must be a positive length";
      }
      (arg == "--epsilon" ? o.UdfRun.Epsilon : o.UdfRun.Spacing) = number;
    }
    else if (arg == "--origin")
    {
      for (int k = 0; k < 3; ++k)
      {
        if (!(problem = value(number)).empty())
        {
          return "--origin needs three numbers X Y Z";
        }
        o.UdfRun.Origin[k] = number;
      }
    }
    else if (arg == "--array")
    {
      if (i + 1 >= argc)
      {
        return "--array needs the name of the distance array";
      }
      o.UdfRun.Array = argv[++i];
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      return "unknown option " + arg + " (see --help)";
    }
    else
    {
      positional.push_back(arg);
    }
  }
  if (help)
  {
    return "";
  }
  if (positional.size() != 2)
  {
    return "expected INPUT and OUTPUT_DIR (see --help)";
  }
  o.Input = positional[0];
  o.OutputDir = positional[1];
  return "";
}

// Writes a stage's outputs, one file name per port, and notes them.
void WriteOutputs(vtkPolyDataAlgorithm* stage, std::initializer_list<const char*> names,
  const std::filesystem::path& dir, std::vector<std::string>& written)
{
  int port = 0;
  for (const char* name : names)
  {
    const std::string path = (dir / name).string();
    WriteVtp(stage->GetOutput(port++), path);
    written.push_back(path);
  }
}

// The primitives of a skeletal diagram as one mesh, each triangle with its
// element's ElementType and ElementId as cell data (one file for any viewer).
vtkSmartPointer<vtkPolyData> JoinPrimitives(vtkPartitionedDataSetCollection* primitives)
{
  vtkNew<vtkAppendPolyData> append;
  for (unsigned int e = 0; e < primitives->GetNumberOfPartitionedDataSets(); ++e)
  {
    auto* mesh = vtkPolyData::SafeDownCast(primitives->GetPartition(e, 0));
    if (!mesh || mesh->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkNew<vtkPolyData> labelled;
    labelled->ShallowCopy(mesh);
    for (const char* name : { "ElementType", "ElementId" })
    {
      vtkNew<vtkIdTypeArray> label;
      label->SetName(name);
      label->SetNumberOfTuples(mesh->GetNumberOfCells());
      label->FillValue(static_cast<vtkIdType>(mesh->GetFieldData()->GetArray(name)->GetTuple1(0)));
      labelled->GetCellData()->AddArray(label);
    }
    labelled->GetFieldData()->Initialize();
    append->AddInputData(labelled);
  }
  vtkSmartPointer<vtkPolyData> joined = vtkSmartPointer<vtkPolyData>::New();
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    joined->ShallowCopy(append->GetOutput());
  }
  return joined;
}

}

int main(int argc, char** argv)
{
  medialaxis::TuneHeap(argv);
  // Errors are reported below, once, in the tool's own words.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  Options o;
  bool help = false;
  const std::string problem = Parse(argc, argv, o, help);
  if (help)
  {
    PrintHelp();
    return Ok;
  }
  if (!problem.empty())
  {
    std::cerr << "medial-axis: " << problem << "\n";
    return BadArguments;
  }
  if (o.Udf)
  {
    medialaxis::tool::UdfOptions& udf = o.UdfRun;
    udf.Field = o.Input;
    udf.OutputDir = o.OutputDir;
    udf.Report = o.Report;
    udf.Samples = o.Samples > 0 ? o.Samples : 0;
    udf.Target = o.Target > 0 ? o.Target : 0;
    udf.Seed = o.Seed;
    udf.Threads = o.Threads;
    udf.Quiet = o.Quiet;
    return medialaxis::tool::RunUdf(udf);
  }
  // Offscreen rendering needs an X display: run under a virtual one.
  if (!o.Screenshot.empty() && !std::getenv("DISPLAY"))
  {
    if (std::getenv("MEDIALAXIS_UNDER_XVFB"))
    {
      std::cerr << "medial-axis: --screenshot needs an X display, and xvfb-run gave none\n";
      return BadArguments;
    }
    setenv("MEDIALAXIS_UNDER_XVFB", "1", 1);
    std::vector<char*> args{ const_cast<char*>("xvfb-run"), const_cast<char*>("-a"),
      const_cast<char*>("-s"), const_cast<char*>("-screen 0 1280x1024x24") };
    for (int i = 0; i < argc; ++i)
    {
      args.push_back(argv[i]);
    }
    args.push_back(nullptr);
    execvp("xvfb-run", args.data());
    std::cerr << "medial-axis: --screenshot needs an X display or xvfb-run (Debian package "
                 "xvfb)\n";
    return BadArguments;
  }
  if (!MakeOutputFolder(o.OutputDir))
  {
    return BadArguments;
  }
  const bool showProgress = !o.Quiet && isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();

  // Read and validate: problems of the input exit with code 3.
  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(o.Input.c_str());
  LastError readError;
  Observe(reader, readError, nullptr);
  reader->Update();
  if (!readError.Message.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    // The reader's message names the file and, for malformed files, the line.
    std::cerr << "medial-axis: cannot read "
              << (readError.Message.empty() ? o.Input + ": no points" : readError.Message) << "\n";
    return BadInput;
  }
  vtkNew<vtkMedialSurfaceValidator> validator;
  validator->SetInputConnection(reader->GetOutputPort());
  validator->SetRepairSelfIntersections(o.Repair);
  LastError validationError;
  Observe(validator, validationError, nullptr);
  validator->Update();
  if (!validator->GetValid())
  {
    std::cerr << "medial-axis: invalid surface " << o.Input << ": " << validator->GetErrorMessage()
              << "\n";
    return BadInput;
  }

  vtkPolyData* surface = validator->GetOutput();
  if (validator->GetRepaired() && !o.Quiet)
  {
    if (validator->GetWrapped())
    {
      std::cout << "  repaired: " << validator->GetNumberOfCrossingPairs()
                << " pairs of crossing triangles could not be resolved exactly; the surface was "
                   "wrapped instead, within "
                << 100.0 * validator->GetRepairDeviation() << "% of the diagonal of the input\n";
    }
    else
    {
      std::cout << "  repaired: " << validator->GetNumberOfCrossingPairs()
                << " pairs of crossing triangles resolved into the outer boundary, area "
                << validator->GetRemovedArea() << " inside removed\n";
    }
  }
  medialaxis::SharpEdgeContent sharpEdges;
  if (o.AutomaticPreset)
  {
    sharpEdges = medialaxis::MeasureSharpEdgeContent(
      medialaxis::OutwardTriangleMesh(surface), vtkMath::RadiansFromDegrees(o.FeatureAngle));
    o.Cad = medialaxis::LooksLikeCad(sharpEdges);
  }

  vtkNew<vtkStructuralMedialAxis> structural;
  if (o.Cad)
  {
    structural->SetPresetToCAD();
  }
  if (o.Samples > 0)
  {
    structural->SetNumberOfSamples(o.Samples);
  }
  if (o.Target > 0)
  {
    structural->SetTargetNumberOfVertices(o.Target);
  }
  if (o.Sharp >= 0)
  {
    structural->SetPreserveSharpFeatures(o.Sharp == 1);
  }
  structural->SetMaximumError(o.MaximumError);
  structural->SetFeatureAngle(o.FeatureAngle);
  structural->SetFeatureNormalFiltering(o.FeatureNormalFiltering);
  structural->SetFringeCollapses(o.FringeCollapses);
  structural->SetErrorBands(o.ErrorBands);
  structural->SetHairAngle(o.HairAngle);
  structural->SetFinBudget(o.FinBudget);
  structural->SetPleatAngle(o.PleatAngle);
  structural->SetEulerNeutralSpikeCollapses(o.SpikeCollapses);
  structural->SetClampRadiiToAtlas(o.ClampRadii);
  structural->SetAbsorbSpikes(o.AbsorbSpikes);
  structural->SetFinalFit(o.FinalFit);
  structural->SetFitSpikeRepair(o.SpikeRepair);
  structural->SetFitSheetBoundaryRadii(o.FitBoundaryRadii);
  structural->SetStrategy(
    o.QMat ? vtkStructuralMedialAxis::QMat : vtkStructuralMedialAxis::Structural);
  structural->SetRandomSeed(o.Seed);
  if (o.Adaptive >= 0)
  {
    structural->SetAdaptiveSampling(o.Adaptive == 1);
  }
  structural->SetNumberOfThreads(o.Threads);
  structural->SetGenerateEnvelope(o.Envelope);
  // A repaired surface is repaired again inside (the same result), so that
  // the correspondence names the input's triangles (InputTriangleId).
  structural->SetRepairSelfIntersections(o.Repair);
  structural->SetInputConnection(
    validator->GetRepaired() ? reader->GetOutputPort() : validator->GetOutputPort());
  ProgressBar bar{ "medial axis" };
  LastError computeError;
  Observe(structural, computeError, showProgress ? &bar : nullptr);
  structural->Update();
  vtkPolyData* mat = structural->GetOutput(0);
  if (!computeError.Message.empty() || mat->GetNumberOfPoints() == 0)
  {
    std::cerr << "medial-axis: computation failed: "
              << (computeError.Message.empty() ? "empty result" : computeError.Message) << "\n";
    return ComputationFailed;
  }

  const std::filesystem::path dir(o.OutputDir);
  std::vector<std::string> written;
  vtkNew<vtkMedialAxisWriter> maWriter;
  maWriter->SetInputData(mat);
  const std::string maPath = (dir / "mat.ma").string();
  maWriter->SetFileName(maPath.c_str());
  if (maWriter->Write() != 1 || !WriteVtp(mat, (dir / "mat.vtp").string()))
  {
    std::cerr << "medial-axis: cannot write into " << o.OutputDir << "\n";
    return ComputationFailed;
  }
  written.push_back(maPath);
  written.push_back((dir / "mat.vtp").string());
  if (o.Correspondence)
  {
    const std::string path = (dir / "correspondence.vtp").string();
    WriteVtp(vtkPolyData::SafeDownCast(structural->GetOutputDataObject(1)), path);
    written.push_back(path);
  }
  double envelopeSeconds = 0.0;
  if (o.Envelope)
  {
    // The one-click filter made it (port 3).
    envelopeSeconds = FieldValue(mat, "EnvelopeSeconds");
    const std::string path = (dir / "envelope.vtp").string();
    WriteVtp(vtkPolyData::SafeDownCast(structural->GetOutputDataObject(3)), path);
    written.push_back(path);
  }
  double filletSeconds = 0.0;
  vtkNew<vtkFilletDetector> fillets;
  if (o.Fillets)
  {
    fillets->SetInputData(0, mat);
    fillets->SetInputData(1, vtkPolyData::SafeDownCast(structural->GetOutputDataObject(1)));
    fillets->SetInputConnection(2, validator->GetOutputPort());
    ProgressBar filletBar{ "fillets" };
    if (!UpdateStage(
          fillets, "fillet detection", showProgress ? &filletBar : nullptr, filletSeconds))
    {
      return ComputationFailed;
    }
    WriteOutputs(fillets, { "fillets.vtp", "fillet_faces.vtp" }, dir, written);
  }
  double structureSeconds = 0.0;
  vtkNew<vtkMedialStructure> structure;
  if (o.Structure)
  {
    structure->SetInputData(0, mat);
    if (o.Fillets)
    {
      structure->SetInputData(1, fillets->GetOutput(0));
    }
    structure->SetInputData(2, vtkPolyData::SafeDownCast(structural->GetOutputDataObject(1)));
    if (!UpdateStage(structure, "structure", nullptr, structureSeconds))
    {
      return ComputationFailed;
    }
    WriteOutputs(structure, { "structure.vtp", "seams.vtp" }, dir, written);
  }
  double midSurfaceSeconds = 0.0;
  vtkNew<vtkMidSurfaceExtractor> midSurface;
  if (o.MidSurface)
  {
    midSurface->SetInputConnection(0, validator->GetOutputPort());
    midSurface->SetInputData(1, mat);
    if (!UpdateStage(midSurface, "mid-surface", nullptr, midSurfaceSeconds))
    {
      return ComputationFailed;
    }
    WriteOutputs(midSurface, { "mid_surface.vtp" }, dir, written);
  }
  double diagramSeconds = 0.0;
  vtkNew<vtkMedialSkeletalDiagram> diagram;
  if (o.SkeletalDiagram > 0)
  {
    diagram->SetInputConnection(0, validator->GetOutputPort());
    diagram->SetInputDataObject(1, mat);
    diagram->SetMaximumElements(o.SkeletalDiagram);
    if (!UpdateStage(diagram, "skeletal diagram", nullptr, diagramSeconds))
    {
      return ComputationFailed;
    }
    const std::string skeletonPath = (dir / "skeleton.vtp").string();
    WriteVtp(diagram->GetSkeleton(), skeletonPath);
    written.push_back(skeletonPath);
    const std::string primitivesPath = (dir / "primitives.vtp").string();
    WriteVtp(JoinPrimitives(diagram->GetPrimitives()), primitivesPath);
    written.push_back(primitivesPath);
    const std::string reconstructionPath = (dir / "reconstruction.vtp").string();
    WriteVtp(diagram->GetReconstruction(), reconstructionPath);
    written.push_back(reconstructionPath);
  }
  if (!o.Screenshot.empty())
  {
    const std::string problem = medialaxis::WriteScreenshot(o.Screenshot, validator->GetOutput(),
      o.MidSurface ? midSurface->GetOutput() : mat, o.Fillets ? fillets->GetOutput(1) : nullptr,
      o.Fillets ? fillets->GetOutput(0) : nullptr, 1200, 900);
    if (!problem.empty())
    {
      std::cerr << "medial-axis: screenshot failed: " << problem << "\n";
      return ComputationFailed;
    }
    written.push_back(o.Screenshot);
  }
  // Two-sided distances between the surface and a reconstruction of it (the
  // MAT's envelope, or the skeletal diagram's union), absolute.
  struct Distances
  {
    double Hausdorff = -1.0, HausdorffPercent = -1.0, ToEnvelope = -1.0, ToSurface = -1.0,
           Mean = -1.0, MeanPercent = -1.0;
  };
  auto measure = [&](vtkPolyData* reconstruction, const char* what, double& seconds,
                   vtkMedialReconstructionError* error, Distances& d)
  {
    error->SetInputConnection(0, validator->GetOutputPort());
    error->SetInputData(1, reconstruction);
    error->SetNumberOfThreads(o.Threads);
    ProgressBar errorBar{ "error" };
    if (!UpdateStage(error, what, showProgress ? &errorBar : nullptr, seconds))
    {
      return false;
    }
    d.Hausdorff = error->GetHausdorff();
    d.HausdorffPercent = error->GetHausdorffPercent();
    d.ToEnvelope = error->GetHausdorffSurfaceToEnvelope();
    d.ToSurface = error->GetHausdorffEnvelopeToSurface();
    d.Mean = FieldValue(error->GetOutput(0), "Mean");
    d.MeanPercent = FieldValue(error->GetOutput(0), "MeanPercent");
    return true;
  };
  Distances matDistances, diagramDistances;
  double errorSeconds = 0.0, diagramErrorSeconds = 0.0;
  vtkNew<vtkMedialReconstructionError> error, diagramError;
  if (o.Error)
  {
    if (!measure(mat, "error measurement", errorSeconds, error, matDistances))
    {
      return ComputationFailed;
    }
    const std::string path = (dir / "distance.vtp").string();
    WriteVtp(error->GetOutput(0), path);
    written.push_back(path);
    if (o.SkeletalDiagram > 0 && diagram->GetReconstruction()->GetNumberOfPolys() > 0 &&
      !measure(diagram->GetReconstruction(), "skeletal diagram error measurement",
        diagramErrorSeconds, diagramError, diagramDistances))
    {
      return ComputationFailed;
    }
  }
  const double hausdorff = matDistances.Hausdorff, hausdorffPercent = matDistances.HausdorffPercent,
               toEnvelope = matDistances.ToEnvelope, toSurface = matDistances.ToSurface;
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  medialaxis::MedialMesh mesh;
  medialaxis::PolyDataToMedialMesh(mat, mesh);
  const medialaxis::MedialMeshQuality quality = medialaxis::MeasureQuality(mesh);
  const medialaxis::MedialCleanliness clean =
    medialaxis::MeasureCleanliness(mesh, surface->GetLength());
  const long long euler = medialaxis::EulerCharacteristic(mesh);
  const medialaxis::MedialMeshCheck check = medialaxis::ValidateMedialMesh(mesh);
  std::cout << "medial axis of " << o.Input << ": " << mesh.Centers.size() << " spheres, "
            << quality.Triangles << " slabs, Euler characteristic " << euler << ", " << seconds
            << " s";
  if (o.Error)
  {
    std::cout << ", two-sided Hausdorff " << hausdorffPercent << "% of the diagonal";
  }
  std::cout << "\n  sheets: " << clean.Sheets << ", N80 " << clean.SheetsFor80PercentArea
            << ", largest " << 100.0 * clean.LargestSheetAreaFraction << "% of the area, fins "
            << 100.0 * clean.FinAreaFraction << "% of the area, folds "
            << 100.0 * clean.FoldedEdgeFraction << "% of the sheet edges, boundary "
            << clean.BoundaryLength << " and junctions " << clean.JunctionLength
            << " diagonals long\n";
  if (o.AutomaticPreset)
  {
    std::cout << "  preset: " << (o.Cad ? "cad" : "organic") << " (sharp-edge creases "
              << sharpEdges.Ratio() << " times the square root of the area, " << sharpEdges.Creases
              << " creases)\n";
  }
  vtkPolyData* filletLines = fillets->GetOutput(0);
  if (o.Fillets)
  {
    vtkCellData* cells = filletLines->GetCellData();
    std::cout << "  " << filletLines->GetNumberOfCells() << " fillets\n";
    for (vtkIdType f = 0; f < filletLines->GetNumberOfCells(); ++f)
    {
      std::cout << "    fillet " << f << ": radius " << cells->GetArray("MeanRadius")->GetTuple1(f)
                << " (from " << cells->GetArray("MinimumRadius")->GetTuple1(f) << " to "
                << cells->GetArray("MaximumRadius")->GetTuple1(f) << "), length "
                << cells->GetArray("Length")->GetTuple1(f) << "\n";
    }
  }
  auto typeName = [](int t)
  { return medialaxis::MedialVertexTypeName(static_cast<medialaxis::MedialVertexType>(t)); };
  if (o.Structure)
  {
    std::cout << "  " << structure->GetNumberOfSheets() << " sheets, "
              << structure->GetNumberOfSeams() << " seams; spheres:";
    for (int t = 0; t < medialaxis::NumberOfMedialVertexTypes; ++t)
    {
      std::cout << (t ? ", " : " ") << structure->GetNumberOfVerticesOfType(t) << " "
                << typeName(t);
    }
    std::cout << "\n";
  }
  if (o.MidSurface)
  {
    std::cout << "  mid-surface: " << midSurface->GetNumberOfWalls() << " walls from "
              << midSurface->GetNumberOfWallSheets() << " medial sheets, wall thickness "
              << midSurface->GetEstimatedWallThickness() << ", "
              << midSurface->GetNumberOfJunctionEdges() << " junction edges\n";
  }
  if (o.SkeletalDiagram > 0)
  {
    vtkPolyData* skeleton = diagram->GetSkeleton();
    std::cout << "  skeletal diagram: " << skeleton->GetNumberOfPoints() << " vertices, "
              << skeleton->GetNumberOfLines() << " edges, " << skeleton->GetNumberOfPolys()
              << " triangles, surface within " << 100.0 * diagram->GetReachedError()
              << "% of the diagonal of the primitives";
    if (diagramDistances.Hausdorff >= 0.0)
    {
      std::cout << ", reconstruction: two-sided Hausdorff " << diagramDistances.HausdorffPercent
                << "%, mean " << diagramDistances.MeanPercent << "%";
    }
    std::cout << "\n";
  }
  for (const std::string& path : written)
  {
    std::cout << "  wrote " << path << "\n";
  }

  if (!o.Report.empty())
  {
    std::ostringstream json;
    json.precision(10);
    json << "{\n  \"input\": " << JsonString(o.Input)
         << ",\n  \"surface\": {\"points\": " << surface->GetNumberOfPoints()
         << ", \"triangles\": " << surface->GetNumberOfPolys()
         << ", \"area\": " << FieldValue(surface, "Area")
         << ", \"volume\": " << FieldValue(surface, "Volume") << "}"
         << ",\n  \"repair\": {\"repaired\": " << (validator->GetRepaired() ? "true" : "false")
         << ", \"crossing_pairs\": " << validator->GetNumberOfCrossingPairs()
         << ", \"removed_area\": " << validator->GetRemovedArea() << ", \"method\": "
         << (!validator->GetRepaired()    ? "null"
                : validator->GetWrapped() ? "\"alpha wrap\""
                                          : "\"resolved crossings\"")
         << ", \"deviation\": " << validator->GetRepairDeviation() << "}"
         << ",\n  \"preset\": " << (o.Cad ? "\"cad\"" : "\"organic\"")
         << ", \"preset_chosen\": " << (o.AutomaticPreset ? "\"auto\"" : "\"given\"");
    if (o.AutomaticPreset)
    {
      json << ", \"sharp_edges\": {\"crease_ratio\": " << sharpEdges.Ratio()
           << ", \"creases\": " << sharpEdges.Creases
           << ", \"crease_length\": " << sharpEdges.CreaseLength
           << ", \"sharp_length\": " << sharpEdges.SharpLength << "}";
    }
    json << ",\n  \"parameters\": {"
         << "\"samples\": " << structural->GetNumberOfSamples()
         << ", \"adaptive_sampling\": " << (structural->GetAdaptiveSampling() ? "true" : "false")
         << ", \"target\": " << structural->GetTargetNumberOfVertices()
         << ", \"max_error\": " << structural->GetMaximumError()
         << ", \"preserve_sharp_features\": "
         << (structural->GetPreserveSharpFeatures() ? "true" : "false")
         << ", \"feature_angle\": " << o.FeatureAngle
         << ", \"feature_normal_filtering\": " << o.FeatureNormalFiltering
         << ", \"fringe_collapses\": "
         << (o.FringeCollapses == vtkAtlasMedialAxisSimplifier::FringeAutomatic ? "\"automatic\""
                : o.FringeCollapses == vtkAtlasMedialAxisSimplifier::FringeOn   ? "\"on\""
                                                                                : "\"off\"")
         << ", \"error_bands\": "
         << (o.ErrorBands == vtkAtlasMedialAxisSimplifier::BandsAutomatic ? "\"automatic\""
                : o.ErrorBands == vtkAtlasMedialAxisSimplifier::BandsOn   ? "\"on\""
                                                                          : "\"off\"")
         << ", \"hair_angle\": " << o.HairAngle << ", \"fin_budget\": " << o.FinBudget
         << ", \"pleat_angle\": " << o.PleatAngle << ", \"euler_neutral_spike_collapses\": "
         << (structural->GetEulerNeutralSpikeCollapses() ? "true" : "false")
         << ", \"absorb_spikes\": " << (structural->GetAbsorbSpikes() ? "true" : "false")
         << ", \"clamp_radii_to_atlas\": "
         << (structural->GetClampRadiiToAtlas() ? "true" : "false")
         << ", \"final_fit\": " << (structural->GetFinalFit() ? "true" : "false")
         << ", \"spike_repair\": " << structural->GetFitSpikeRepair()
         << ", \"fit_boundary_radii\": "
         << (structural->GetFitSheetBoundaryRadii() ? "true" : "false")
         << ", \"strategy\": " << (o.QMat ? "\"qmat\"" : "\"structural\"")
         << ", \"seed\": " << o.Seed << ", \"threads\": " << o.Threads << "},\n  \"seconds\": {";
    const char* stages[] = { "Sampling", "RestrictedVoronoi", "VoronoiMedialAxis", "Simplification",
      "Total" };
    for (int k = 0; k < 5; ++k)
    {
      json << (k ? ", " : "") << JsonString(stages[k]) << ": "
           << FieldValue(mat, (std::string(stages[k]) + "Seconds").c_str());
    }
    json << ", \"QueueInitialisation\": " << FieldValue(mat, "QueueInitialisationSeconds")
         << ", \"Envelope\": " << envelopeSeconds << ", \"Fillets\": " << filletSeconds
         << ", \"Structure\": " << structureSeconds << ", \"MidSurface\": " << midSurfaceSeconds
         << ", \"SkeletalDiagram\": " << diagramSeconds << ", \"Error\": " << errorSeconds
         << ", \"SkeletalDiagramError\": " << diagramErrorSeconds << ", \"wall\": " << seconds
         << "},\n  \"peak_memory_mb\": " << PeakMegabytes()
         << ",\n  \"counts\": {\"sites\": " << FieldValue(mat, "Sites")
         << ", \"initial_vertices\": " << FieldValue(mat, "InitialVertices")
         << ", \"initial_triangles\": " << FieldValue(mat, "InitialTriangles")
         << ", \"vertices\": " << mesh.Centers.size()
         << ", \"edges\": " << medialaxis::AllEdges(mesh).size()
         << ", \"triangles\": " << mesh.Faces.size()
         << ", \"boundary_edges\": " << quality.BoundaryEdges
         << ", \"nonmanifold_edges\": " << quality.NonManifoldEdges
         << ", \"collapses\": " << FieldValue(mat, "Collapses")
         << ", \"fin_collapses\": " << FieldValue(mat, "FinCollapses")
         << ", \"eroded_triangles\": " << FieldValue(mat, "ErodedTriangles")
         << ", \"fringe_collapses_used\": "
         << (FieldValue(mat, "FringeCollapsesUsed") == 1.0 ? "true" : "false")
         << ", \"error_bands_used\": "
         << (FieldValue(mat, "ErrorBandsUsed") == 1.0 ? "true" : "false")
         << ", \"error_target_evaluations\": " << FieldValue(mat, "ErrorTargetEvaluations")
         << ", \"error_target_hausdorff_percent\": "
         << 100.0 * FieldValue(mat, "ErrorTargetHausdorff") << "},\n"
         << "  \"valid\": " << (check.IsValid() ? "true" : "false")
         << ", \"validity_problem\": " << JsonString(check.Message) << ",\n"
         << "  \"euler_characteristic\": " << euler << ",\n  \"triangle_quality\": {"
         << "\"degenerate\": " << quality.DegenerateTriangles
         << ", \"folded\": " << quality.FoldedTriangles
         << ", \"mean_min_angle_deg\": " << quality.MeanMinimumAngle
         << ", \"percent_min_angle_below_30\": " << quality.PercentMinimumAngleBelow30
         << ", \"mean_q\": " << quality.MeanQuality << "},\n  \"cleanliness\": {"
         << "\"sheets\": " << clean.Sheets << ", \"n80\": " << clean.SheetsFor80PercentArea
         << ", \"largest_sheet_area_percent\": " << 100.0 * clean.LargestSheetAreaFraction
         << ", \"fin_area_percent\": " << 100.0 * clean.FinAreaFraction
         << ", \"folds_percent\": " << 100.0 * clean.FoldedEdgeFraction
         << ", \"junction_edges\": " << clean.JunctionEdges
         << ", \"boundary_length_diagonals\": " << clean.BoundaryLength
         << ", \"junction_length_diagonals\": " << clean.JunctionLength << "}";
    if (o.Fillets)
    {
      vtkCellData* cells = filletLines->GetCellData();
      json << ",\n  \"fillets\": [";
      for (vtkIdType f = 0; f < filletLines->GetNumberOfCells(); ++f)
      {
        json << (f ? ",\n    " : "\n    ")
             << "{\"mean_radius\": " << cells->GetArray("MeanRadius")->GetTuple1(f)
             << ", \"minimum_radius\": " << cells->GetArray("MinimumRadius")->GetTuple1(f)
             << ", \"maximum_radius\": " << cells->GetArray("MaximumRadius")->GetTuple1(f)
             << ", \"length\": " << cells->GetArray("Length")->GetTuple1(f)
             << ", \"surface_area\": " << cells->GetArray("SurfaceArea")->GetTuple1(f) << "}";
      }
      json << "]";
    }
    if (o.Structure)
    {
      json << ",\n  \"structure\": {\"sheets\": " << structure->GetNumberOfSheets()
           << ", \"seams\": " << structure->GetNumberOfSeams() << ", \"spheres\": {";
      for (int t = 0; t < medialaxis::NumberOfMedialVertexTypes; ++t)
      {
        json << (t ? ", " : "") << JsonString(typeName(t)) << ": "
             << structure->GetNumberOfVerticesOfType(t);
      }
      json << "}, \"tangent_component_agreement\": "
           << FieldValue(structure->GetOutput(0), "TangentComponentAgreement") << "}";
    }
    if (o.MidSurface)
    {
      json << ",\n  \"mid_surface\": {\"walls\": " << midSurface->GetNumberOfWalls()
           << ", \"wall_sheets\": " << midSurface->GetNumberOfWallSheets()
           << ", \"wall_thickness\": " << midSurface->GetEstimatedWallThickness()
           << ", \"junction_edges\": " << midSurface->GetNumberOfJunctionEdges()
           << ", \"triangles\": " << midSurface->GetOutput()->GetNumberOfPolys() << "}";
    }
    if (o.SkeletalDiagram > 0)
    {
      vtkPolyData* skeleton = diagram->GetSkeleton();
      json << ",\n  \"skeletal_diagram\": {\"vertices\": " << skeleton->GetNumberOfPoints()
           << ", \"edges\": " << skeleton->GetNumberOfLines()
           << ", \"triangles\": " << skeleton->GetNumberOfPolys()
           << ", \"error\": " << diagram->GetReachedError()
           << ", \"mean_error\": " << FieldValue(skeleton, "MeanError")
           << ", \"failed_elements\": " << FieldValue(skeleton, "FailedElements")
           << ", \"continuous_parameters\": " << FieldValue(skeleton, "ContinuousParameters");
      if (diagramDistances.Hausdorff >= 0.0)
      {
        json << ", \"hausdorff\": {\"two_sided\": " << diagramDistances.Hausdorff
             << ", \"two_sided_percent\": " << diagramDistances.HausdorffPercent
             << ", \"surface_to_envelope\": " << diagramDistances.ToEnvelope
             << ", \"envelope_to_surface\": " << diagramDistances.ToSurface
             << ", \"mean_two_sided\": " << diagramDistances.Mean
             << ", \"mean_two_sided_percent\": " << diagramDistances.MeanPercent << "}";
      }
      json << "}";
    }
    if (o.Error)
    {
      json << ",\n  \"hausdorff\": {\"two_sided\": " << hausdorff
           << ", \"two_sided_percent\": " << hausdorffPercent
           << ", \"surface_to_envelope\": " << toEnvelope
           << ", \"envelope_to_surface\": " << toSurface
           << ", \"mean_two_sided\": " << matDistances.Mean
           << ", \"mean_two_sided_percent\": " << matDistances.MeanPercent << "}";
    }
    json << "\n}\n";
    if (!WriteReport(o.Report, json.str()))
    {
      return ComputationFailed;
    }
  }
  return Ok;
}
