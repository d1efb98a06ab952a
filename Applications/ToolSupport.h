// SPDX-License-Identifier: GPL-3.0-or-later
// What the command-line tool's commands share: a progress bar, errors
// caught from the algorithms, files, JSON text, peak memory.
#ifndef MedialAxis_ToolSupport_h
#define MedialAxis_ToolSupport_h

#include "vtkErrorEventText.h"
#include "vtkMedialMeshConversion.h"

#include "vtkAlgorithm.h"

#include <cstdio>
#include <string>

class vtkObject;
class vtkPolyData;

namespace medialaxis
{
namespace tool
{
// Progress bar on stderr, redrawn when the percentage changes.
struct ProgressBar
{
  std::string Label;
  int Last = -1;
  static void Callback(vtkObject* caller, unsigned long, void* clientData, void*)
  {
    auto* self = static_cast<ProgressBar*>(clientData);
    const double f = static_cast<vtkAlgorithm*>(caller)->GetProgress();
    const int percent = static_cast<int>(100.0 * f);
    if (percent == self->Last)
    {
      return;
    }
    self->Last = percent;
    const int width = 40, filled = percent * width / 100;
    std::fprintf(stderr, "\r%-12s [%s%s] %3d%%", self->Label.c_str(),
      std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(), percent);
    if (percent >= 100)
    {
      std::fputc('\n', stderr);
    }
    std::fflush(stderr);
  }
};

// Collects the last error of an algorithm (printed by us, not by VTK).
struct LastError
{
  std::string Message;
  static void Callback(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    static_cast<LastError*>(clientData)->Message = medialaxis::ErrorEventMessage(callData);
  }
};

/// Catches the algorithm's errors into `error` and, with a bar, draws its
/// progress.
void Observe(vtkAlgorithm* algorithm, LastError& error, ProgressBar* bar);

/// Writes binary VTK XML poly data; false when the file cannot be written.
bool WriteVtp(vtkPolyData* data, const std::string& path);

/// Updates a stage, timing it; prints what failed and returns false on an
/// error.
bool UpdateStage(vtkAlgorithm* stage, const char* what, ProgressBar* bar, double& seconds);

/// The first value of a field-data array, 0 when it is missing.
inline double FieldValue(vtkPolyData* data, const char* name)
{
  return medialaxis::GetFieldValue(data, name);
}

/// A JSON string literal.
std::string JsonString(const std::string& s);

/// Creates the output folder (and its parents); prints why and returns
/// false when it cannot.
bool MakeOutputFolder(const std::string& folder);

/// Writes the JSON report and says so; prints why and returns false when
/// it cannot.
bool WriteReport(const std::string& path, const std::string& json);

/// The process's peak resident memory, in MB.
double PeakMegabytes();
}
}

#endif
