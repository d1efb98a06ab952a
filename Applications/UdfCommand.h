// SPDX-License-Identifier: GPL-3.0-or-later
// medial-axis --udf: the surface of an unsigned distance field.
#ifndef MedialAxis_UdfCommand_h
#define MedialAxis_UdfCommand_h

#include <array>
#include <string>

namespace medialaxis
{
namespace tool
{
struct UdfOptions
{
  std::string Field, OutputDir, Report, Array;
  double Epsilon = 0.0;                    // 0: twice the spacing
  double Spacing = 0.0;                    // .npy only
  std::array<double, 3> Origin{ 0, 0, 0 }; // .npy only
  long long Samples = 0, Target = 0;       // 0: from the shell's size
  bool Snap = false, Quiet = false;
  int Seed = 0, Threads = 0;
};

/// Reads the field (.vti, legacy .vtk structured points, or .npy with the
/// spacing), extracts its surface with vtkUnsignedDistanceSurfaceExtractor
/// and writes surface.vtp, shell.vtp and the report. Returns the tool's
/// exit code.
int RunUdf(const UdfOptions& options);
}
}

#endif
