# SPDX-License-Identifier: BSD-3-Clause
# IO/: readers and writers of the SplineViz module (included from cmake/module/CMakeLists.txt).
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkIFEMReader"
  "${SPLINEVIZ_FOLDER}/vtkLRSplineReader")
# Plain C++ parser of the LRSplines text and GoTools g2 formats.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkLRSplineParser")
# IFEM's HDF5 results: the HDF5 layer (the only user of the HDF5 C library)
# and the VTK blocks of its spline and Lagrange patches.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkIFEMBlockBuilder"
  "${SPLINEVIZ_FOLDER}/vtkIFEMFile"
  "${SPLINEVIZ_FOLDER}/vtkIFEMLagrangePatch")
# Neuroimaging: NIfTI diffusion tensor volumes and scalar / vector volumes,
# MRtrix .tck / TrackVis .trk tractograms, read and written.
list(APPEND splineviz_classes
  "${SPLINEVIZ_FOLDER}/vtkNIfTIReaderBase"
  "${SPLINEVIZ_FOLDER}/vtkNIfTITensorReader"
  "${SPLINEVIZ_FOLDER}/vtkNIfTIVolumeReader"
  "${SPLINEVIZ_FOLDER}/vtkTractogramReader"
  "${SPLINEVIZ_FOLDER}/vtkTractogramWriter")
# Plain C++ shared by the tractogram reader and writer: the headers of the
# formats, byte order, the TrackVis voxel-mm to RAS+ mm map.
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkTractogramFormats")
# Plain C++ NIfTI-1/2 file layer shared by the NIfTI readers: header parsing
# and validation, the affine and the image placement, voxels (gzip through
# VTK's zlib).
list(APPEND splineviz_private_classes
  "${SPLINEVIZ_FOLDER}/vtkNIfTIFile")
list(APPEND splineviz_private_headers
  "${SPLINEVIZ_FOLDER}/vtkSplineVizNameList.h")
