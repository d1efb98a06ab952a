// SPDX-License-Identifier: GPL-3.0-or-later
#include "ToolOptions.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace medialaxis
{
namespace tool
{
namespace
{
bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0';
}
}

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
  --curve-skeleton      a curve skeleton from the MAT: centre lines with the
                        inscribed radius at every node and one loop per
                        handle; write curve_skeleton.vtp (point data Radius,
                        NodeType, BranchId), curve_skeleton.swc (SWC, loops
                        broken and listed), curve_skeleton.json (the graph)
                        and segmentation.vtp (the surface with point data
                        NodeId and BranchId); the report gives the counts and
                        the loops
  --error               measure the two-sided Hausdorff distance between the
                        surface and the envelope (% of the bounding-box
                        diagonal) and write distance.vtp (the surface with
                        point data Distance)
  --screenshot FILE     render the result offscreen into a PNG: the surface
                        (semi-transparent, fillet faces coloured with
                        --fillets), the MAT coloured by radius (with
                        --mid-surface the mid-surface by thickness, with
                        --curve-skeleton the skeleton by radius instead)
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
  --version             the version and the commit built
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

std::string Parse(int argc, char** argv, Options& o, bool& help, bool& version)
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
    else if (arg == "--version")
    {
      version = true;
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
    else if (arg == "--curve-skeleton")
    {
      o.CurveSkeleton = true;
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
  if (help || version)
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
}
}
