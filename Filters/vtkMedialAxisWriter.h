// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMedialAxisWriter
 * @brief   Writes a medial mesh to a `.ma` file.
 *
 * The input must be a valid medial mesh (point data `Radius`, triangles,
 * lines and vertices only, no duplicate or degenerate cells); otherwise the
 * writer reports why and writes nothing. Every edge is listed, face edges
 * included, because Q-MAT-style consumers look edges up per face. Numbers
 * are written with 17 significant digits, so reading back is exact.
 */
#ifndef vtkMedialAxisWriter_h
#define vtkMedialAxisWriter_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkWriter.h"

#include <string>

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialAxisWriter : public vtkWriter
{
public:
  static vtkMedialAxisWriter* New();
  vtkTypeMacro(vtkMedialAxisWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Name of the file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// Why the last write failed ("" after success).
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

protected:
  vtkMedialAxisWriter();
  ~vtkMedialAxisWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  std::string ErrorMessage;

private:
  vtkMedialAxisWriter(const vtkMedialAxisWriter&) = delete;
  void operator=(const vtkMedialAxisWriter&) = delete;
};

#endif
