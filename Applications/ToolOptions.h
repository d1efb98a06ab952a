// SPDX-License-Identifier: GPL-3.0-or-later
// The command line of medial-axis: its options, their help text and their
// parsing.
#ifndef medialaxis_ToolOptions_h
#define medialaxis_ToolOptions_h

#include "UdfCommand.h"
#include "vtkAtlasMedialAxisSimplifier.h"

#include "vtkType.h"

#include <string>

namespace medialaxis
{
namespace tool
{
/// What the command line asks for (-1 or 0: from the preset, as noted).
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
  bool CurveSkeleton = false;
  bool Udf = false; // INPUT is an unsigned distance field
  medialaxis::tool::UdfOptions UdfRun;
};

/// Prints the usage, every option and the exit codes.
void PrintHelp();

/// Reads the arguments into `o`; sets `help` or `version` when asked for
/// (the rest may then be incomplete). Returns an error message, or "" when
/// the arguments are usable.
std::string Parse(int argc, char** argv, Options& o, bool& help, bool& version);
}
}

#endif
