// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkSurfaceFileReader
 * @brief   Reads a surface mesh from OBJ, OFF, PLY, STL, VTP or legacy VTK files.
 *
 * Picks the reader from the file extension (case-insensitive): .obj
 * (vtkOBJReader), .off (vtkOFFReader), .ply (vtkPLYReader), .stl
 * (vtkSTLReader), .vtp (vtkXMLPolyDataReader), .vtk (vtkPolyDataReader).
 * The mesh is passed on as read: OBJ files with per-corner normals arrive as
 * triangle soups, which surface preparation merges. An unknown extension, a
 * missing file or a reader failure gives an error naming the file and an
 * empty output.
 */
#ifndef vtkSurfaceFileReader_h
#define vtkSurfaceFileReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkMedialAxisFiltersModule.h"

#include <string>

class VTKMEDIALAXISFILTERS_EXPORT vtkSurfaceFileReader : public vtkAbstractPolyDataReader
{
public:
  static vtkSurfaceFileReader* New();
  vtkTypeMacro(vtkSurfaceFileReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Why the last read failed ("" after success).
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /// True when the extension of `fileName` is one this reader handles.
  static bool IsSupportedExtension(const char* fileName);

protected:
  vtkSurfaceFileReader();
  ~vtkSurfaceFileReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string ErrorMessage;

private:
  vtkSurfaceFileReader(const vtkSurfaceFileReader&) = delete;
  void operator=(const vtkSurfaceFileReader&) = delete;
};

#endif
