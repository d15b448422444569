// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ParticleFile.hpp"

#include "io/XmlFile.hpp"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace mpm::io {

namespace {

static_assert(sizeof(vtkTypeInt64) == sizeof(std::int64_t), "vtkTypeInt64 must be 64 bits");

[[noreturn]] void cannotRead(const std::filesystem::path& file, const std::string& why) {
    throw std::runtime_error("cannot read " + file.string() + ": " + why);
}

/// A contiguous double array viewing `values`.
vtkSmartPointer<vtkDoubleArray> makeDoubleArray(const std::vector<double>& values, int components,
                                                vtkIdType tuples) {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetNumberOfComponents(components);
    if (values.empty()) {
        array->SetNumberOfTuples(tuples);
    } else {
        // Borrowed, not copied (save = 1: VTK never frees it): `values` outlives the writer,
        // and a copy would double the memory of writing a large cloud.
        array->SetArray(const_cast<double*>(values.data()), static_cast<vtkIdType>(values.size()),
                        1);
    }
    return array;
}

/// A contiguous Int64 array viewing `values` (borrowed like makeDoubleArray's).
vtkSmartPointer<vtkTypeInt64Array> makeInt64Array(const std::vector<std::int64_t>& values,
                                                  int components, vtkIdType tuples) {
    auto array = vtkSmartPointer<vtkTypeInt64Array>::New();
    array->SetNumberOfComponents(components);
    if (values.empty()) {
        array->SetNumberOfTuples(tuples);
    } else {
        array->SetArray(reinterpret_cast<vtkTypeInt64*>(const_cast<std::int64_t*>(values.data())),
                        static_cast<vtkIdType>(values.size()), 1);
    }
    return array;
}

template <class Source, class Target>
void convertValues(const Source* source, std::size_t count, std::vector<Target>& target) {
    target.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        target[i] = static_cast<Target>(source[i]);
    }
}

/// Copy every value of `array` into `target`, converting from the array's native type.
/// Returns false for a data type that is not a plain number.
template <class Target> bool copyValues(vtkDataArray* array, std::vector<Target>& target) {
    const auto count = static_cast<std::size_t>(array->GetNumberOfTuples()) *
                       static_cast<std::size_t>(array->GetNumberOfComponents());
    if (count == 0) {
        target.clear();
        return true;
    }
    void* raw = array->GetVoidPointer(0);
    switch (array->GetDataType()) {
        vtkTemplateMacro(convertValues(static_cast<const VTK_TT*>(raw), count, target));
    default:
        return false;
    }
    return true;
}

bool isFloatingType(int dataType) {
    return dataType == VTK_DOUBLE || dataType == VTK_FLOAT;
}

void checkCloud(const std::filesystem::path& file, const PointCloud& cloud) {
    if (cloud.points.size() % 3 != 0) {
        cannotWrite(file, "number of point coordinates is not a multiple of 3");
    }
    const std::size_t n = cloud.size();
    for (const PointArray& a : cloud.arrays) {
        if (a.components < 1) {
            cannotWrite(file, "array '" + a.name + "' has fewer than one component");
        }
        if (!a.f64.empty() && !a.i64.empty()) {
            cannotWrite(file, "array '" + a.name + "' has both double and integer values");
        }
        const std::size_t expected = n * static_cast<std::size_t>(a.components);
        const std::size_t actual = a.isInteger() ? a.i64.size() : a.f64.size();
        if (actual != expected) {
            cannotWrite(file, "array '" + a.name + "' has " + std::to_string(actual) +
                                  " values, expected " + std::to_string(expected));
        }
    }
}

} // namespace

const PointArray* PointCloud::find(const std::string& name) const {
    for (const PointArray& a : arrays) {
        if (a.name == name) {
            return &a;
        }
    }
    return nullptr;
}

void writeVtu(const std::filesystem::path& file, const PointCloud& cloud) {
    checkCloud(file, cloud);
    const auto n = static_cast<vtkIdType>(cloud.size());

    vtkNew<vtkPoints> points;
    points->SetData(makeDoubleArray(cloud.points, 3, n));

    // One VTK_VERTEX per point: offsets 0..n, connectivity 0..n-1.
    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
    offsets->SetNumberOfValues(n + 1);
    connectivity->SetNumberOfValues(n);
    vtkIdType* off = offsets->GetPointer(0);
    vtkIdType* conn = connectivity->GetPointer(0);
    for (vtkIdType i = 0; i < n; ++i) {
        off[i] = i;
        conn[i] = i;
    }
    off[n] = n;
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);

    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    grid->SetCells(VTK_VERTEX, cells);

    vtkPointData* pointData = grid->GetPointData();
    for (const PointArray& a : cloud.arrays) {
        vtkSmartPointer<vtkDataArray> array;
        if (a.isInteger()) {
            array = makeInt64Array(a.i64, a.components, n);
        } else {
            array = makeDoubleArray(a.f64, a.components, n);
        }
        array->SetName(a.name.c_str());
        pointData->AddArray(array);
    }

    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writeXmlAtomically(*writer, grid, file);
}

PointCloud readVtu(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        cannotRead(file, "no such file");
    }

    vtkNew<ErrorObserver> errors;
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    if (reader->CanReadFile(file.string().c_str()) == 0) {
        cannotRead(file, "not a VTK XML UnstructuredGrid file");
    }
    reader->SetFileName(file.string().c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    if (errors->failed() || reader->GetErrorCode() != 0 || grid == nullptr) {
        cannotRead(file, errors->message().empty() ? "not a readable VTK XML UnstructuredGrid"
                                                   : errors->message());
    }

    PointCloud cloud;
    const vtkIdType n = grid->GetNumberOfPoints();
    if (n > 0) {
        vtkPoints* points = grid->GetPoints();
        if (points == nullptr || points->GetData() == nullptr ||
            points->GetData()->GetNumberOfComponents() != 3 ||
            !copyValues(points->GetData(), cloud.points)) {
            cannotRead(file, "invalid points");
        }
    }

    vtkPointData* pointData = grid->GetPointData();
    for (int i = 0; i < pointData->GetNumberOfArrays(); ++i) {
        vtkDataArray* array = pointData->GetArray(i);
        if (array == nullptr) {
            continue; // string / variant arrays are not particle data
        }
        if (array->GetNumberOfTuples() != n) {
            cannotRead(file, std::string("array '") + (array->GetName() ? array->GetName() : "") +
                                 "' does not have one tuple per point");
        }
        PointArray a;
        a.name = array->GetName() != nullptr ? array->GetName() : "";
        a.components = array->GetNumberOfComponents();
        a.integer = !isFloatingType(array->GetDataType());
        const bool copied = a.integer ? copyValues(array, a.i64) : copyValues(array, a.f64);
        if (!copied) {
            continue; // e.g. a bit array
        }
        cloud.arrays.push_back(std::move(a));
    }
    return cloud;
}

void writeScalarFile(const std::filesystem::path& file, const std::string& key, double value) {
    std::ostringstream os;
    os.precision(17);
    os << key << ": " << value << "\n";
    std::filesystem::create_directories(file.parent_path());
    writeTextAtomic(file, os.str());
}

void writeIndexFlags(const std::filesystem::path& file, const std::string& key,
                     const std::vector<std::pair<Index, int>>& pairs) {
    std::ostringstream index, flags;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        index << (k ? ", " : "") << pairs[k].first;
        flags << (k ? ", " : "") << pairs[k].second;
    }
    std::filesystem::create_directories(file.parent_path());
    writeTextAtomic(file, key + ": [" + index.str() + "]\nflags: [" + flags.str() + "]\n");
}

void writeTextAtomic(const std::filesystem::path& file, const std::string& text) {
    const std::filesystem::path tmp = tmpName(file);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            cannotWrite(file);
        }
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.flush();
        if (!out) {
            out.close();
            removeQuietly(tmp);
            cannotWrite(file);
        }
        out.close();
        if (out.fail()) {
            removeQuietly(tmp);
            cannotWrite(file);
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        removeQuietly(tmp);
        cannotWrite(file, ec.message());
    }
}

} // namespace mpm::io
