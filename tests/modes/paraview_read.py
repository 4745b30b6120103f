"""Opens a table's XDMF companion with ParaView's own XDMF readers (run with pvpython; optional check of
fields_test.sh): prints, per reader, the points, cells and node arrays it read and the range of every
array's first component, one line each, and exits 1 if a reader fails or reads nothing."""
import os
import sys

from paraview.simple import OpenDataFile, XDMFReader, Xdmf3ReaderS, servermanager

# ParaView's Xdmf3 readers mis-resolve the HDF5 file next to an XDMF named without a folder: absolute path.
path = os.path.abspath(sys.argv[1])
status = 0
for name, make in (("XDMFReader", lambda: XDMFReader(FileNames=[path])),
                   ("Xdmf3ReaderS", lambda: Xdmf3ReaderS(FileName=[path])),
                   ("OpenDataFile", lambda: OpenDataFile(path))):
    try:
        reader = make()
        reader.UpdatePipeline()
        data = servermanager.Fetch(reader)
        while data.IsA("vtkMultiBlockDataSet"):
            data = data.GetBlock(0)
        pd = data.GetPointData()
        arrays = {pd.GetArrayName(i): (pd.GetArray(i).GetNumberOfComponents(), pd.GetArray(i).GetRange(0))
                  for i in range(pd.GetNumberOfArrays())}
        print("%s points %d cells %d arrays %s" % (name, data.GetNumberOfPoints(), data.GetNumberOfCells(),
                                                   sorted(arrays.items())))
        if data.GetNumberOfCells() == 0 or not arrays:
            status = 1
    except Exception as e:  # noqa: BLE001 - any reader failure is the finding
        print("%s FAILED %s" % (name, e))
        status = 1
sys.exit(status)
