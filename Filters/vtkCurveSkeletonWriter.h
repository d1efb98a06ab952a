// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkCurveSkeletonWriter
 * @brief   Writes a curve skeleton as SWC or as a JSON graph.
 *
 * The input is vtkMedialCurveSkeleton's output 0 (points with `Radius`,
 * polylines). SWC, the neuron morphology format: a line "id type x y z
 * radius parent" per node, one tree per piece grown breadth-first from its
 * node of largest radius (type 1, the others 0), the edges left out to
 * break loops listed in "# loop a b" comment lines. JSON: nodes (id,
 * position, radius, type, branch), edges (source, target, length), branches
 * (node ids), cycle rank and components. Numbers have 17 significant digits.
 */
#ifndef vtkCurveSkeletonWriter_h
#define vtkCurveSkeletonWriter_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkWriter.h"

#include <string>

class VTKMEDIALAXISFILTERS_EXPORT vtkCurveSkeletonWriter : public vtkWriter
{
public:
  static vtkCurveSkeletonWriter* New();
  vtkTypeMacro(vtkCurveSkeletonWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Name of the file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  enum
  {
    FormatFromExtension = 0, // .json: JSON, anything else: SWC
    FormatSwc = 1,
    FormatJson = 2
  };
  ///@{
  /// The file format (default: from the file name's extension).
  vtkSetClampMacro(FileFormat, int, FormatFromExtension, FormatJson);
  vtkGetMacro(FileFormat, int);
  ///@}

  ///@{
  /// Lines written at the top of an SWC file as comments (e.g. the source
  /// mesh and the units).
  vtkSetStdStringFromCharMacro(Header);
  vtkGetCharFromStdStringMacro(Header);
  ///@}

  /// Why the last write failed ("" after success).
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

protected:
  vtkCurveSkeletonWriter();
  ~vtkCurveSkeletonWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  int FileFormat = FormatFromExtension;
  std::string Header = "curve skeleton";
  std::string ErrorMessage;

private:
  vtkCurveSkeletonWriter(const vtkCurveSkeletonWriter&) = delete;
  void operator=(const vtkCurveSkeletonWriter&) = delete;
};

#endif
