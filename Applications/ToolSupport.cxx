// SPDX-License-Identifier: GPL-3.0-or-later
#include "ToolSupport.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace medialaxis
{
namespace tool
{

void Observe(vtkAlgorithm* algorithm, LastError& error, ProgressBar* bar)
{
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(&LastError::Callback);
  onError->SetClientData(&error);
  algorithm->AddObserver(vtkCommand::ErrorEvent, onError);
  if (bar)
  {
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetCallback(&ProgressBar::Callback);
    onProgress->SetClientData(bar);
    algorithm->AddObserver(vtkCommand::ProgressEvent, onProgress);
  }
}

bool WriteVtp(vtkPolyData* data, const std::string& path)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->SetDataModeToBinary();
  return writer->Write() == 1;
}

bool UpdateStage(vtkAlgorithm* stage, const char* what, ProgressBar* bar, double& seconds)
{
  LastError error;
  Observe(stage, error, bar);
  const auto begin = std::chrono::steady_clock::now();
  stage->Update();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  stage->RemoveObservers(vtkCommand::ErrorEvent);
  stage->RemoveObservers(vtkCommand::ProgressEvent);
  if (!error.Message.empty())
  {
    std::cerr << "medial-axis: " << what << " failed: " << error.Message << "\n";
    return false;
  }
  return true;
}

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

double PeakMegabytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

bool MakeOutputFolder(const std::string& folder)
{
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
  {
    std::cerr << "medial-axis: cannot create the output folder " << folder << "\n";
    return false;
  }
  return true;
}

bool WriteReport(const std::string& path, const std::string& json)
{
  std::ofstream file(path);
  file << json;
  if (!file)
  {
    std::cerr << "medial-axis: cannot write the report " << path << "\n";
    return false;
  }
  std::cout << "  wrote " << path << "\n";
  return true;
}
}
}
