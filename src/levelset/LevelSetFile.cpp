// SPDX-License-Identifier: GPL-3.0-or-later
#include "levelset/LevelSetFile.hpp"

#include "io/XmlFile.hpp"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace mpm::levelset {

namespace {

[[noreturn]] void cannotRead(const std::filesystem::path& file, const std::string& why) {
    throw std::runtime_error("cannot read " + file.string() + ": " + why);
}

void addField(vtkFieldData* fd, const char* name, const std::vector<double>& values) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(1);
    a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        a->SetValue(static_cast<vtkIdType>(i), values[i]);
    fd->AddArray(a);
}

std::vector<double> getField(const std::filesystem::path& file, vtkFieldData* fd, const char* name,
                             std::size_t size) {
    vtkDataArray* a = fd != nullptr ? fd->GetArray(name) : nullptr;
    if (a == nullptr) cannotRead(file, std::string("no field data '") + name + "'");
    const auto n = static_cast<std::size_t>(a->GetNumberOfTuples() * a->GetNumberOfComponents());
    if (n != size) {
        cannotRead(file, std::string("field data '") + name + "' has " + std::to_string(n) +
                             " values, expected " + std::to_string(size));
    }
    std::vector<double> v(size);
    const int nc = a->GetNumberOfComponents();
    for (std::size_t i = 0; i < size; ++i) {
        v[i] = a->GetComponent(static_cast<vtkIdType>(i) / nc, static_cast<int>(i) % nc);
    }
    return v;
}

} // namespace

void writeVti(const std::filesystem::path& file, const LevelSet& ls, bool doublePrecision) {
    const RegularGrid& g = ls.grid;
    if (g.values.size() != g.numPoints() || g.values.empty()) {
        io::cannotWrite(file, "the grid values do not match its dimensions");
    }
    vtkNew<vtkImageData> image;
    image->SetDimensions(g.dims[0], g.dims[1], g.dims[2]);
    image->SetOrigin(g.origin.x(), g.origin.y(), g.origin.z());
    image->SetSpacing(g.spacing, g.spacing, g.spacing);

    vtkSmartPointer<vtkDataArray> phi;
    if (doublePrecision) {
        auto a = vtkSmartPointer<vtkDoubleArray>::New();
        a->SetNumberOfTuples(static_cast<vtkIdType>(g.values.size()));
        for (std::size_t i = 0; i < g.values.size(); ++i) {
            a->SetValue(static_cast<vtkIdType>(i), g.values[i]);
        }
        phi = a;
    } else {
        auto a = vtkSmartPointer<vtkFloatArray>::New();
        a->SetNumberOfTuples(static_cast<vtkIdType>(g.values.size()));
        for (std::size_t i = 0; i < g.values.size(); ++i) {
            a->SetValue(static_cast<vtkIdType>(i), static_cast<float>(g.values[i]));
        }
        phi = a;
    }
    phi->SetName("phi");
    image->GetPointData()->AddArray(phi);
    image->GetPointData()->SetActiveScalars("phi");

    vtkFieldData* fd = image->GetFieldData();
    addField(fd, "volume", {ls.volume});
    addField(fd, "centroid", {ls.centroid.x(), ls.centroid.y(), ls.centroid.z()});
    addField(fd, "principalMoments",
             {ls.principalMoments.x(), ls.principalMoments.y(), ls.principalMoments.z()});
    std::vector<double> r(9);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            r[static_cast<std::size_t>(3 * i + j)] = ls.rotation(i, j);
    }
    addField(fd, "rotation", r);

    vtkNew<vtkXMLImageDataWriter> writer;
    io::writeXmlAtomically(*writer, image, file);
}

LevelSet readVti(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) cannotRead(file, "no such file");
    vtkNew<io::ErrorObserver> errors;
    vtkNew<vtkXMLImageDataReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    if (reader->CanReadFile(file.string().c_str()) == 0) {
        cannotRead(file, "not a VTK XML ImageData file");
    }
    reader->SetFileName(file.string().c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    if (errors->failed() || reader->GetErrorCode() != 0 || image == nullptr) {
        cannotRead(file, errors->message().empty() ? "not a readable VTK XML ImageData"
                                                   : errors->message());
    }

    LevelSet ls;
    int dims[3];
    double origin[3], spacing[3];
    image->GetDimensions(dims);
    image->GetOrigin(origin);
    image->GetSpacing(spacing);
    if (std::abs(spacing[0] - spacing[1]) > 1e-12 * std::abs(spacing[0]) ||
        std::abs(spacing[0] - spacing[2]) > 1e-12 * std::abs(spacing[0]) || !(spacing[0] > 0)) {
        cannotRead(file, "the grid spacing is not uniform and positive");
    }
    ls.grid.dims = {dims[0], dims[1], dims[2]};
    ls.grid.origin = Vec3(origin[0], origin[1], origin[2]);
    ls.grid.spacing = spacing[0];
    vtkDataArray* phi = image->GetPointData()->GetArray("phi");
    if (phi == nullptr || phi->GetNumberOfComponents() != 1 ||
        static_cast<std::size_t>(phi->GetNumberOfTuples()) != ls.grid.numPoints()) {
        cannotRead(file, "no point array 'phi' of one value per grid point");
    }
    ls.grid.values.resize(ls.grid.numPoints());
    for (std::size_t i = 0; i < ls.grid.values.size(); ++i) {
        ls.grid.values[i] = phi->GetComponent(static_cast<vtkIdType>(i), 0);
    }

    vtkFieldData* fd = image->GetFieldData();
    ls.volume = getField(file, fd, "volume", 1)[0];
    const auto c = getField(file, fd, "centroid", 3);
    ls.centroid = Vec3(c[0], c[1], c[2]);
    const auto m = getField(file, fd, "principalMoments", 3);
    ls.principalMoments = Vec3(m[0], m[1], m[2]);
    const auto r = getField(file, fd, "rotation", 9);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            ls.rotation(i, j) = r[static_cast<std::size_t>(3 * i + j)];
    }
    return ls;
}

} // namespace mpm::levelset
