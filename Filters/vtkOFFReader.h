// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkOFFReader
 * @brief   Reads a polygon mesh from an ASCII Object File Format (`.off`) file.
 *
 * Accepts `OFF`, `COFF`, `NOFF` and `CNOFF` headers (extra per-vertex and
 * per-face values such as colours are skipped), `#` comments and blank lines.
 * Polygons keep all their vertices: triangulation and cleaning are done by
 * the filters that consume surfaces (see vtkMedialSurfaceValidator).
 * A malformed file gives an error naming the file and line, and an empty
 * output.
 */
#ifndef vtkOFFReader_h
#define vtkOFFReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkMedialAxisFiltersModule.h"

#include <string>

class VTKMEDIALAXISFILTERS_EXPORT vtkOFFReader : public vtkAbstractPolyDataReader
{
public:
  static vtkOFFReader* New();
  vtkTypeMacro(vtkOFFReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Why the last read failed, with the line number ("" after success).
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

protected:
  vtkOFFReader();
  ~vtkOFFReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string ErrorMessage;

private:
  vtkOFFReader(const vtkOFFReader&) = delete;
  void operator=(const vtkOFFReader&) = delete;
};

#endif
