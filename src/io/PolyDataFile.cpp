// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/PolyDataFile.hpp"

#include "io/XmlFile.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstring>
#include <stdexcept>
#include <system_error>

namespace mpm::io {

namespace {

vtkSmartPointer<vtkDoubleArray> makeArray(const std::filesystem::path& file, const DataArray& a,
                                          std::size_t tuples) {
    if (a.components < 1) cannotWrite(file, "array '" + a.name + "' has no components");
    const std::size_t expected = tuples * static_cast<std::size_t>(a.components);
    if (a.values.size() != expected) {
        cannotWrite(file, "array '" + a.name + "' has " + std::to_string(a.values.size()) +
                              " values, expected " + std::to_string(expected));
    }
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(a.name.c_str());
    array->SetNumberOfComponents(a.components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
    if (!a.values.empty()) {
        std::memcpy(array->GetPointer(0), a.values.data(), a.values.size() * sizeof(double));
    }
    return array;
}

} // namespace

void writeVtp(const std::filesystem::path& file, const std::vector<Vec3>& points,
              const std::vector<std::vector<int>>& cells, bool lines,
              const std::vector<DataArray>& pointData, const std::vector<DataArray>& cellData) {
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (int d = 0; d < 3; ++d) {
            coordinates->SetTypedComponent(static_cast<vtkIdType>(i), d, points[i][d]);
        }
    }
    vtkNew<vtkPoints> vtkPts;
    vtkPts->SetData(coordinates);

    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
    offsets->InsertNextValue(0);
    for (const std::vector<int>& cell : cells) {
        for (const int p : cell) {
            if (p < 0 || static_cast<std::size_t>(p) >= points.size()) {
                cannotWrite(file, "cell point index " + std::to_string(p) + " out of range");
            }
            connectivity->InsertNextValue(p);
        }
        offsets->InsertNextValue(connectivity->GetNumberOfValues());
    }
    vtkNew<vtkCellArray> cellArray;
    cellArray->SetData(offsets, connectivity);

    vtkNew<vtkPolyData> poly;
    poly->SetPoints(vtkPts);
    if (lines) {
        poly->SetLines(cellArray);
    } else {
        poly->SetPolys(cellArray);
    }
    for (const DataArray& a : pointData) {
        poly->GetPointData()->AddArray(makeArray(file, a, points.size()));
    }
    for (const DataArray& a : cellData) {
        poly->GetCellData()->AddArray(makeArray(file, a, cells.size()));
    }

    vtkNew<vtkXMLPolyDataWriter> writer;
    writeXmlAtomically(*writer, poly, file);
}

} // namespace mpm::io
