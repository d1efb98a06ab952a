// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMedialAxisReader
 * @brief   Reads a medial mesh from a `.ma` file (Q-MAT, MATFP, Blender MAT add-on).
 *
 * Format: a header line `nv ne nf`, then `v x y z r`, `e i j` and `f i j k`
 * lines (0-based indices). Extra trailing tokens (MATFP's flags), `#`
 * comments and blank lines are accepted. Repeated edges or faces are dropped
 * (counted in the field-data arrays `DuplicateEdges` / `DuplicateFaces`).
 *
 * Output: a medial mesh as in the MedialAxis data contract: the points are
 * sphere centres with point data `Radius` (active scalars), triangles for
 * faces, line cells for edges that bound no face, vertex cells for isolated
 * spheres.
 *
 * A malformed file (missing or bad header counts, fewer or more lines than
 * announced, an index out of range, a negative or NaN radius, a token that is
 * not a number, a face with a repeated vertex) gives an error naming the file
 * and line, an empty output, and GetErrorMessage() returns the message.
 */
#ifndef vtkMedialAxisReader_h
#define vtkMedialAxisReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkMedialAxisFiltersModule.h"

#include <string>

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialAxisReader : public vtkAbstractPolyDataReader
{
public:
  static vtkMedialAxisReader* New();
  vtkTypeMacro(vtkMedialAxisReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Why the last read failed, with the line number ("" after success).
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /// Whether the file looks like a .ma file (for ParaView's reader factory).
  static int CanReadFile(const char* fileName);

protected:
  vtkMedialAxisReader();
  ~vtkMedialAxisReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string ErrorMessage;

private:
  vtkMedialAxisReader(const vtkMedialAxisReader&) = delete;
  void operator=(const vtkMedialAxisReader&) = delete;
};

#endif
