// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ParticleIO.hpp"
#include "core/Error.hpp"

#include <type_traits>

namespace mpm::io {

namespace {

/// Components a value type is written with, and its conversion to and from them.
template <int dim, class T> struct Columns;

template <int dim> struct Columns<dim, double> {
    static constexpr int n = 1;
    static void put(const double& v, double* out, bool) { out[0] = v; }
    static void get(const double* in, double& v) { v = in[0]; }
};
template <int dim> struct Columns<dim, Vec<dim>> {
    static constexpr int n = 3;
    static void put(const Vec<dim>& v, double* out, bool) {
        for (int a = 0; a < dim; ++a)
            out[a] = v[a];
    }
    static void get(const double* in, Vec<dim>& v) {
        for (int a = 0; a < dim; ++a)
            v[a] = in[a];
    }
};
template <int dim> struct Columns<dim, Mat<dim>> {
    static constexpr int n = 9;
    static void put(const Mat<dim>& m, double* out, bool identityPad) {
        for (int a = 0; a < dim; ++a)
            for (int b = 0; b < dim; ++b)
                out[3 * a + b] = m(a, b);
        if (dim == 2 && identityPad) out[8] = 1.0;
    }
    static void get(const double* in, Mat<dim>& m) {
        for (int a = 0; a < dim; ++a)
            for (int b = 0; b < dim; ++b)
                m(a, b) = in[3 * a + b];
    }
};
// Mat3 is Mat<3>: in 3D the specialisation above serves it.
template <> struct Columns<2, Mat3> {
    static constexpr int n = 9;
    static void put(const Mat3& m, double* out, bool) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                out[3 * a + b] = m(a, b);
    }
    static void get(const double* in, Mat3& m) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                m(a, b) = in[3 * a + b];
    }
};

template <class T> constexpr bool isInteger = std::is_integral_v<T>;

template <class T> T zero() {
    if constexpr (std::is_arithmetic_v<T>)
        return T(0);
    else
        return T::Zero();
}

} // namespace

template <int dim> PointCloud toPointCloud(const Particles<dim>& p) {
    const std::size_t n = p.size();
    PointCloud cloud;
    cloud.points.assign(3 * n, 0.0);
    cloud.arrays.reserve(24);
    Particles<dim>::visitTable(
        [&](const FieldInfo& info, const auto& a) {
            using T = typename std::decay_t<decltype(a)>::value_type;
            if (!info.written) return;
            if constexpr (isInteger<T>) {
                std::vector<std::int64_t> out(a.begin(), a.end());
                cloud.arrays.push_back({info.name, 1, {}, std::move(out), true});
            } else if (info.points) {
                for (std::size_t i = 0; i < n; ++i)
                    Columns<dim, T>::put(a[i], &cloud.points[3 * i], false);
            } else {
                constexpr int c = Columns<dim, T>::n;
                std::vector<double> out(c * n, 0.0);
                for (std::size_t i = 0; i < n; ++i)
                    Columns<dim, T>::put(a[i], &out[c * i], info.identityPad);
                cloud.arrays.push_back({info.name, c, std::move(out), {}, false});
            }
        },
        [&](const char* name, double (*value)(const Particles<dim>&, Index)) {
            std::vector<double> out(n);
            for (std::size_t i = 0; i < n; ++i)
                out[i] = value(p, static_cast<Index>(i));
            cloud.arrays.push_back({name, 1, std::move(out), {}, false});
        },
        p);
    return cloud;
}

template <int dim>
void fromPointCloud(const PointCloud& cloud, Particles<dim>& p, const std::string& file) {
    const std::size_t n = cloud.size();
    p.resize(n);
    p.forEachField([&](const FieldInfo& info, auto& a) {
        using T = typename std::decay_t<decltype(a)>::value_type;
        if (!info.restart) {
            std::fill(a.begin(), a.end(), zero<T>());
            return;
        }
        auto missing = [&](int c) {
            return InputError(file, 0, info.name,
                              "restart array missing or with the wrong number of components (" +
                                  std::to_string(c) + " expected); was it written by mpmFoam?");
        };
        if constexpr (isInteger<T>) {
            const PointArray* arr = cloud.find(info.name);
            if (!arr || arr->components != 1 || !arr->isInteger()) throw missing(1);
            for (std::size_t i = 0; i < n; ++i)
                a[i] = static_cast<T>(arr->i64[i]);
        } else if (info.points) {
            for (std::size_t i = 0; i < n; ++i)
                Columns<dim, T>::get(&cloud.points[3 * i], a[i]);
        } else {
            constexpr int c = Columns<dim, T>::n;
            const PointArray* arr = cloud.find(info.name);
            if (!arr || arr->components != c || arr->isInteger()) throw missing(c);
            for (std::size_t i = 0; i < n; ++i)
                Columns<dim, T>::get(&arr->f64[c * i], a[i]);
        }
    });
}

template PointCloud toPointCloud(const Particles<2>&);
template PointCloud toPointCloud(const Particles<3>&);
template void fromPointCloud(const PointCloud&, Particles<2>&, const std::string&);
template void fromPointCloud(const PointCloud&, Particles<3>&, const std::string&);

} // namespace mpm::io
