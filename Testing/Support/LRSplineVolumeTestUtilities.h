// SPDX-License-Identifier: BSD-3-Clause
// The independent reference for vtkLRSplineVolumeMapper: a CPU ray caster
// that evaluates the LR spline exactly in double precision with
// vtkLRSplineField (the CPU element search and Bezier evaluation, tested on
// their own against the LR B-spline definition) or with any evaluator of the
// same interface (Render is a template: lrtest::PhysicalField, written
// independently for curved geometry, or an analytic field), at uniform steps
// (ten times finer than the mapper's finest adaptive step unless a test says
// otherwise), with the transfer functions
// evaluated from the vtkColorTransferFunction / vtkPiecewiseFunction
// themselves (not a table), VTK's opacity correction 1 - (1 - a)^(step /
// unit distance) and front-to-back compositing; isosurfaces by bracketing at
// the fine steps and 60 bisections. Shared by the volume tests and the
// volume benchmark (image error of every method), with the tests' scene
// (Scene) and their curved geometry (Bend, RewriteCoefficients).
#ifndef LRSplineVolumeTestUtilities_h
#define LRSplineVolumeTestUtilities_h

#include "vtkLRSplineBuilder.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineReader.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkPixelBufferObject.h"
#include "vtkPointData.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace lrvolume
{
/// What the reference renders: the mapper's settings that change the picture.
struct Settings
{
  int BlendMode = 0;  ///< 0 composite, 1 MIP, 2 MinIP, 5 isosurface
  int Component = -1; ///< -1: magnitude (vectors), else the component
  double Step = 0.0;  ///< uniform step, data units (> 0)
  bool Shade = false;
  bool Fuchs = false; ///< Fuchs' diffuse model instead of VTK's
  bool EarlyTermination = true;
  std::vector<double> IsoValues;
  /// Optional per-pixel window depth (row-major from the bottom, [0, 1]) where
  /// the rays end (the opaque geometry), and trimming front / back depths.
  const std::vector<float>* EndDepth = nullptr;
  const std::vector<float>* TrimFront = nullptr;
  const std::vector<float>* TrimBack = nullptr;
  /// Clipping planes in data coordinates: kept where n . x + w >= 0.
  std::vector<std::array<double, 4>> ClipPlanes;
};

/// A rendered image: premultiplied RGBA per pixel (doubles), and the eye-ray
/// distance (world) of the first isosurface (or -1).
struct Image
{
  int Width = 0, Height = 0;
  std::vector<double> RGBA;
  std::vector<double> FirstHit;
  std::vector<std::array<double, 3>> FirstHitPoint; ///< data coordinates
};

/// The view of a renderer: clip space to data coordinates and the volume's
/// data-to-world matrix.
struct View
{
  vtkNew<vtkMatrix4x4> ClipToData, DataToClip, DataToWorld;
  double ToLight[3] = { 0, 0, 1 };
  double LightColor[3] = { 1, 1, 1 };
  int Width = 0, Height = 0;

  void Set(vtkRenderer* ren, vtkVolume* vol)
  {
    int* size = ren->GetSize();
    this->Width = size[0];
    this->Height = size[1];
    vtkCamera* cam = ren->GetActiveCamera();
    vtkMatrix4x4* proj =
      cam->GetCompositeProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1);
    this->DataToWorld->DeepCopy(vol->GetMatrix());
    vtkMatrix4x4::Multiply4x4(proj, this->DataToWorld, this->DataToClip);
    vtkMatrix4x4::Invert(this->DataToClip, this->ClipToData);
    const double* p = cam->GetPosition();
    const double* f = cam->GetFocalPoint();
    double n = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      this->ToLight[k] = p[k] - f[k];
      n += this->ToLight[k] * this->ToLight[k];
    }
    for (int k = 0; k < 3; ++k)
    {
      this->ToLight[k] /= std::sqrt(n);
    }
  }

  void Unproject(double x, double y, double z, double out[3]) const
  {
    const double in[4] = { x, y, z, 1.0 };
    double r[4];
    this->ClipToData->MultiplyPoint(in, r);
    for (int k = 0; k < 3; ++k)
    {
      out[k] = r[k] / r[3];
    }
  }

  /// The ray of pixel (i, j) in data coordinates: origin on the near plane,
  /// unit direction.
  void Ray(int i, int j, double origin[3], double dir[3]) const
  {
    const double nx = 2.0 * (i + 0.5) / this->Width - 1.0;
    const double ny = 2.0 * (j + 0.5) / this->Height - 1.0;
    double b[3];
    this->Unproject(nx, ny, -1.0, origin);
    this->Unproject(nx, ny, 1.0, b);
    double n = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      dir[k] = b[k] - origin[k];
      n += dir[k] * dir[k];
    }
    n = std::sqrt(n);
    for (int k = 0; k < 3; ++k)
    {
      dir[k] /= n;
    }
  }

  /// Ray parameter at window depth z in [0, 1] of pixel (i, j).
  double RayDepth(int i, int j, double z, const double origin[3], const double dir[3]) const
  {
    const double nx = 2.0 * (i + 0.5) / this->Width - 1.0;
    const double ny = 2.0 * (j + 0.5) / this->Height - 1.0;
    double p[3];
    this->Unproject(nx, ny, 2.0 * z - 1.0, p);
    return (p[0] - origin[0]) * dir[0] + (p[1] - origin[1]) * dir[1] + (p[2] - origin[2]) * dir[2];
  }

  void ToWorldVector(const double v[3], double w[3]) const
  {
    for (int r = 0; r < 3; ++r)
    {
      w[r] = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        w[r] += this->DataToWorld->GetElement(r, c) * v[c];
      }
    }
  }
};

/// The scalar the mapper renders from the field's value(s) and its gradient
/// (data coordinates).
template <class Field>
inline double Scalar(
  const Field& field, int component, const double* value, const double* gradient, double grad[3])
{
  const int nc = field.GetNumberOfComponents();
  if (nc == 1 || component >= 0)
  {
    const int c = nc == 1 ? 0 : component;
    for (int k = 0; k < 3; ++k)
    {
      grad[k] = gradient[3 * c + k];
    }
    return value[c];
  }
  double m2 = 0.0;
  double g[3] = { 0, 0, 0 };
  for (int c = 0; c < nc; ++c)
  {
    m2 += value[c] * value[c];
    for (int k = 0; k < 3; ++k)
    {
      g[k] += value[c] * gradient[3 * c + k];
    }
  }
  const double m = std::sqrt(m2);
  for (int k = 0; k < 3; ++k)
  {
    grad[k] = m > 0 ? g[k] / m : 0.0;
  }
  return m;
}

/// The interval [t0, t1] of the ray (o, d) through pixel (i, j) that
/// Render() samples: the field's bounds, the end depth, the clipping planes
/// and the trimming depths of `settings`; false when it is empty.
inline bool RayInterval(const View& view, const Settings& settings, const double bounds[6], int i,
  int j, const double o[3], const double d[3], double& t0, double& t1)
{
  const vtkIdType pix = static_cast<vtkIdType>(j) * view.Width + i;
  t0 = 0.0;
  t1 = 1e300;
  for (int k = 0; k < 3; ++k)
  {
    const double a = (bounds[2 * k] - o[k]) / d[k];
    const double b = (bounds[2 * k + 1] - o[k]) / d[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (settings.EndDepth)
  {
    t1 = std::min(t1, view.RayDepth(i, j, (*settings.EndDepth)[pix], o, d));
  }
  bool visible = true;
  for (const auto& pl : settings.ClipPlanes)
  {
    const double denom = pl[0] * d[0] + pl[1] * d[1] + pl[2] * d[2];
    const double dist = pl[0] * o[0] + pl[1] * o[1] + pl[2] * o[2] + pl[3];
    if (std::abs(denom) < 1e-20)
    {
      visible = visible && dist >= 0;
      continue;
    }
    const double t = -dist / denom;
    if (denom > 0)
    {
      t0 = std::max(t0, t);
    }
    else
    {
      t1 = std::min(t1, t);
    }
  }
  if (settings.TrimFront && settings.TrimBack)
  {
    const double f = (*settings.TrimFront)[pix], b = (*settings.TrimBack)[pix];
    if (f >= 1.0 || b <= 0.0)
    {
      visible = false;
    }
    else
    {
      t0 = std::max(t0, view.RayDepth(i, j, f, o, d));
      t1 = std::min(t1, view.RayDepth(i, j, b, o, d));
    }
  }
  return visible && t1 > t0;
}

/// Color `rgb` of a sample lit with its gradient `grad` (data coordinates)
/// into `out`, as the volume mapper does (two-sided; `inverse`: the inverse
/// of the data-to-world matrix, whose transpose takes gradients to normals;
/// material: ambient, diffuse, specular, specular power; toEye: the unit
/// world direction to the eye).
inline void ShadeSample(const View& view, const Settings& settings, vtkMatrix4x4* inverse,
  const double material[4], const double toEye[3], const double rgb[3], const double grad[3],
  double out[3])
{
  std::copy(rgb, rgb + 3, out);
  if (!settings.Shade)
  {
    return;
  }
  double nw[3];
  for (int r = 0; r < 3; ++r)
  {
    nw[r] = inverse->GetElement(0, r) * grad[0] + inverse->GetElement(1, r) * grad[1] +
      inverse->GetElement(2, r) * grad[2];
  }
  const double len = std::sqrt(nw[0] * nw[0] + nw[1] * nw[1] + nw[2] * nw[2]);
  if (!(len > 0))
  {
    return;
  }
  for (double& c : nw)
  {
    c /= len;
  }
  if (nw[0] * toEye[0] + nw[1] * toEye[1] + nw[2] * toEye[2] < 0)
  {
    for (double& c : nw)
    {
      c = -c;
    }
  }
  const double* l = view.ToLight;
  const double ln = l[0] * nw[0] + l[1] * nw[1] + l[2] * nw[2];
  if (settings.Fuchs)
  {
    for (int k = 0; k < 3; ++k)
    {
      out[k] = rgb[k] * std::max(0.4, std::abs(ln));
    }
    return;
  }
  const double ka = material[0], kd = material[1], ks = material[2], sp = material[3];
  const double diffuse = std::max(ln, 0.0);
  double h[3] = { l[0] + toEye[0], l[1] + toEye[1], l[2] + toEye[2] };
  const double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  const double hn = hl > 0 ? (h[0] * nw[0] + h[1] * nw[1] + h[2] * nw[2]) / hl : 0.0;
  const double specular = diffuse > 0 ? std::pow(std::max(hn, 0.0), sp) : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    out[k] = rgb[k] * (ka + kd * diffuse * view.LightColor[k]) + ks * specular * view.LightColor[k];
  }
}

/// The iso values crossed between the samples (prevT, prevS) and (t, s) (a
/// value met exactly at a sample counts once, arriving), each with the ray
/// parameter of its crossing refined by bisection on `sample` (t -> value,
/// see Render()): (t, iso) pairs, nearest first.
template <class Sample>
std::vector<std::pair<double, double>> IsoCrossings(const Sample& sample,
  const std::vector<double>& isoValues, double prevT, double prevS, double t, double s)
{
  std::vector<std::pair<double, double>> roots; // (t, iso)
  for (double c : isoValues)
  {
    if ((prevS - c) * (s - c) < 0 || (s == c && prevS != c))
    {
      double lo = prevT, hi = t, flo = prevS - c;
      for (int it = 0; it < 60; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        double sm, gm[3];
        const double fm = sample(mid, sm, gm) ? sm - c : flo;
        if ((fm < 0) == (flo < 0))
        {
          lo = mid;
          flo = fm;
        }
        else
        {
          hi = mid;
        }
      }
      roots.emplace_back(0.5 * (lo + hi), c);
    }
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

/// The CPU reference rendering of `field` as `vol` (its property) is seen by
/// `view`. Field: vtkLRSplineField, or an independent evaluator with the same
/// GetBounds, GetNumberOfComponents and EvaluateWithHint (e.g.
/// lrtest::PhysicalField for curved geometry).
template <class Field>
inline Image Render(const Field& field, vtkVolume* vol, const View& view, const Settings& settings)
{
  Image image;
  image.Width = view.Width;
  image.Height = view.Height;
  const vtkIdType n = static_cast<vtkIdType>(view.Width) * view.Height;
  image.RGBA.assign(4 * n, 0.0);
  image.FirstHit.assign(n, -1.0);
  image.FirstHitPoint.assign(n, { 0, 0, 0 });
  vtkVolumeProperty* property = vol->GetProperty();
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  const double unit = property->GetScalarOpacityUnitDistance(0);
  const double material[4] = { property->GetAmbient(0), property->GetDiffuse(0),
    property->GetSpecular(0), property->GetSpecularPower(0) };
  double bounds[6];
  field.GetBounds(bounds);
  // The normal matrix (inverse transpose of the linear part).
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(view.DataToWorld, inverse);
  const int nc = field.GetNumberOfComponents();

  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<double> value(nc), gradient(3 * nc);
      for (vtkIdType pix = begin; pix < end; ++pix)
      {
        const int i = static_cast<int>(pix % view.Width);
        const int j = static_cast<int>(pix / view.Width);
        double o[3], d[3];
        view.Ray(i, j, o, d);
        double dw[3];
        view.ToWorldVector(d, dw);
        const double worldPerData = std::sqrt(dw[0] * dw[0] + dw[1] * dw[1] + dw[2] * dw[2]);
        double toEye[3] = { -dw[0] / worldPerData, -dw[1] / worldPerData, -dw[2] / worldPerData };
        double t0, t1;
        if (!RayInterval(view, settings, bounds, i, j, o, d, t0, t1))
        {
          continue;
        }
        // The element of the previous sample is tried first (the same
        // result as a full search: vtkLRSplineField::EvaluateWithHint).
        int hintPatch = -1;
        vtkIdType hintElement = -1;
        auto sample = [&](double t, double& s, double grad[3]) -> bool
        {
          const double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
          if (field.EvaluateWithHint(x, value.data(), gradient.data(), hintPatch, hintElement) < 0)
          {
            return false;
          }
          s = Scalar(field, settings.Component, value.data(), gradient.data(), grad);
          return true;
        };
        auto shade = [&](const double rgb[3], const double grad[3], double out[3])
        { ShadeSample(view, settings, inverse, material, toEye, rgb, grad, out); };
        double* px = &image.RGBA[4 * pix];
        const double h = settings.Step;
        const long long steps = static_cast<long long>(std::ceil((t1 - t0) / h));
        if (settings.BlendMode == 0)
        {
          double acc[4] = { 0, 0, 0, 0 };
          for (long long k = 0; k < steps; ++k)
          {
            const double a = t0 + k * h;
            const double b = std::min(t1, a + h);
            double s, grad[3];
            if (!sample(0.5 * (a + b), s, grad))
            {
              continue;
            }
            double rgb[3];
            ctf->GetColor(s, rgb);
            const double alpha0 = std::min(1.0, std::max(0.0, otf->GetValue(s)));
            const double alpha =
              1.0 - std::pow(std::max(0.0, 1.0 - alpha0), (b - a) * worldPerData / unit);
            double c[3];
            shade(rgb, grad, c);
            for (int q = 0; q < 3; ++q)
            {
              acc[q] += (1.0 - acc[3]) * alpha * c[q];
            }
            acc[3] += (1.0 - acc[3]) * alpha;
            if (settings.EarlyTermination && acc[3] > 0.99)
            {
              break;
            }
          }
          std::copy(acc, acc + 4, px);
        }
        else if (settings.BlendMode == 1 || settings.BlendMode == 2)
        {
          bool found = false;
          double extreme = settings.BlendMode == 1 ? -1e300 : 1e300;
          for (long long k = 0; k <= steps; ++k)
          {
            double s, grad[3];
            if (sample(std::min(t1, t0 + k * h), s, grad))
            {
              found = true;
              extreme = settings.BlendMode == 1 ? std::max(extreme, s) : std::min(extreme, s);
            }
          }
          if (found)
          {
            double rgb[3];
            ctf->GetColor(extreme, rgb);
            const double a = std::min(1.0, std::max(0.0, otf->GetValue(extreme)));
            px[0] = rgb[0] * a;
            px[1] = rgb[1] * a;
            px[2] = rgb[2] * a;
            px[3] = a;
          }
        }
        else
        {
          double acc[4] = { 0, 0, 0, 0 };
          double prevT = t0, prevS = 0.0;
          bool prevValid = false;
          for (long long k = 0; k <= steps && acc[3] <= 0.99; ++k)
          {
            const double t = std::min(t1, t0 + k * h);
            double s, grad[3];
            const bool valid = sample(t, s, grad);
            if (valid && prevValid)
            {
              for (const auto& r : IsoCrossings(sample, settings.IsoValues, prevT, prevS, t, s))
              {
                double sr, gr[3];
                sample(r.first, sr, gr);
                double rgb[3], c[3];
                ctf->GetColor(r.second, rgb);
                const double a = std::min(1.0, std::max(0.0, otf->GetValue(r.second)));
                shade(rgb, gr, c);
                for (int q = 0; q < 3; ++q)
                {
                  acc[q] += (1.0 - acc[3]) * a * c[q];
                }
                acc[3] += (1.0 - acc[3]) * a;
                if (image.FirstHit[pix] < 0)
                {
                  image.FirstHit[pix] = r.first * worldPerData;
                  for (int q = 0; q < 3; ++q)
                  {
                    image.FirstHitPoint[pix][q] = o[q] + r.first * d[q];
                  }
                }
              }
            }
            if (valid)
            {
              prevS = s;
            }
            prevValid = valid;
            prevT = t;
          }
          std::copy(acc, acc + 4, px);
        }
      }
    });
  return image;
}

/// 8-bit RGB of premultiplied `image` over `background` (rounded; with
/// `round` false, in 8-bit units but not rounded, to compare with a
/// floating-point rendering, see ReadRGBFloat).
inline std::vector<double> OverBackground(
  const Image& image, const double background[3], bool round = true)
{
  const std::size_t n = image.RGBA.size() / 4;
  std::vector<double> rgb(3 * n);
  for (std::size_t p = 0; p < n; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = image.RGBA[4 * p + c] + (1.0 - image.RGBA[4 * p + 3]) * background[c];
      const double u = 255.0 * std::min(1.0, std::max(0.0, v));
      rgb[3 * p + c] = round ? std::round(u) : u;
    }
  }
  return rgb;
}

/// The window's RGB (front buffer after Render), rows from the bottom.
inline std::vector<double> ReadRGB(vtkRenderWindow* win)
{
  const int* size = win->GetSize();
  vtkNew<vtkUnsignedCharArray> data;
  win->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, data, 0);
  std::vector<double> rgb(3 * static_cast<std::size_t>(size[0]) * size[1]);
  for (std::size_t i = 0; i < rgb.size(); ++i)
  {
    rgb[i] = data->GetValue(static_cast<vtkIdType>(i));
  }
  return rgb;
}

/// RGB in 8-bit units, not rounded, of a floating-point color texture (e.g.
/// the ColorTexture of a vtkFramebufferPass with ColorFormat Float32 that
/// the renderer drew into), rows from the bottom. The RMS of two 8-bit
/// images is dominated by rounding where they differ by a small fraction
/// of a level (it grows like the square root of the difference); renderings
/// read this way show the methods' own error instead.
inline std::vector<double> ReadRGBFloat(vtkTextureObject* texture)
{
  std::vector<double> rgb;
  if (!texture || texture->GetComponents() != 4)
  {
    return rgb;
  }
  const std::size_t n = static_cast<std::size_t>(texture->GetWidth()) * texture->GetHeight();
  vtkPixelBufferObject* pbo = texture->Download();
  if (!pbo)
  {
    return rgb;
  }
  const float* p = static_cast<const float*>(pbo->MapPackedBuffer());
  if (p)
  {
    rgb.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgb[3 * i + c] = 255.0 * std::min(1.0f, std::max(0.0f, p[4 * i + c]));
      }
    }
    pbo->UnmapPackedBuffer();
  }
  pbo->Delete();
  return rgb;
}

/// The window's depth buffer, rows from the bottom.
inline std::vector<float> ReadDepth(vtkRenderWindow* win)
{
  const int* size = win->GetSize();
  vtkNew<vtkFloatArray> z;
  win->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, z);
  return std::vector<float>(z->GetPointer(0), z->GetPointer(0) + z->GetNumberOfValues());
}

/// RMS difference per channel (8-bit units).
inline double RMS(const std::vector<double>& a, const std::vector<double>& b)
{
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    s += (a[i] - b[i]) * (a[i] - b[i]);
  }
  return std::sqrt(s / static_cast<double>(a.size()));
}

/// Number of pixels (RGB triples) that differ from `background` by more than
/// `tolerance` in some channel.
inline long long CountNonBackground(
  const std::vector<double>& rgb, const double background[3], double tolerance = 1.0)
{
  long long count = 0;
  for (std::size_t p = 0; p + 2 < rgb.size(); p += 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::abs(rgb[p + c] - std::round(255.0 * background[c])) > tolerance)
      {
        ++count;
        break;
      }
    }
  }
  return count;
}

/// Write 8-bit RGB (rows from the bottom) as a PNG, for inspection; with
/// `other`, the absolute difference amplified 8 times.
inline void WritePNG(const std::vector<double>& rgb, int width, int height, const std::string& path,
  const std::vector<double>* other = nullptr)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (std::size_t i = 0; i < rgb.size(); ++i)
  {
    const double v = other ? 8.0 * std::abs(rgb[i] - (*other)[i]) : rgb[i];
    p[i] = static_cast<unsigned char>(std::min(255.0, std::max(0.0, v)));
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
}

/// A dyadic locally refined volume written as .lr to `path` (false on
/// failure): degree `degree`, uniform breaks (4 elements per direction),
/// `levels` halving refinements around `focus`, two components (a smooth
/// trigonometric field and a quadratic), so the octree and the look-up
/// texture apply.
inline bool WriteDyadicVolume(
  const int degree[3], const double focus[3], int levels, const std::string& path)
{
  vtkLRSplineBuilder builder;
  std::vector<double> breaks[3];
  for (int d = 0; d < 3; ++d)
  {
    for (int i = 0; i <= 4; ++i)
    {
      breaks[d].push_back(i / 4.0);
    }
  }
  std::string error;
  if (!builder.InitializeTensorProduct(degree, breaks, 2, &error))
  {
    return false;
  }
  builder.SetCoefficientsFromGreville(
    [](const double g[3], double* c)
    {
      c[0] = std::sin(3 * g[0]) * std::cos(2 * g[1]) + g[2];
      c[1] = g[0] * g[1] - g[2] * g[2];
    });
  for (int l = 0; l < levels; ++l)
  {
    if (!builder.RefineAt(focus, 0.5, &error))
    {
      return false;
    }
  }
  std::ofstream out(path);
  builder.GetPatch().Write(out);
  return static_cast<bool>(out);
}

/// A locally refined scalar LR-spline volume (written as .lr and read back
/// with vtkLRSplineReader, the path of real files): quadratic, non-dyadic
/// breakpoints, `levels` golden-section and halving refinements around two
/// focus points, the field a sum of two smooth blobs plus a slow ramp.
/// `sharpness` divides the blobs' squared widths: with 20, the blobs are
/// narrower than the coarse elements, so only the refined elements resolve
/// them (the refinement matters for the picture).
inline vtkSmartPointer<vtkMultiBlockDataSet> RefinedScalarVolume(
  const std::string& path, int levels, vtkIdType* elements = nullptr, double sharpness = 1.0)
{
  vtkLRSplineBuilder builder;
  const int degree[3] = { 2, 2, 2 };
  std::vector<double> breaks[3];
  for (int d = 0; d < 3; ++d)
  {
    for (int i = 0; i <= 6; ++i)
    {
      double t = i / 6.0;
      if (i > 0 && i < 6)
      {
        t += 0.02 * std::sin(1.3 * i + d) / std::sqrt(2.0);
      }
      breaks[d].push_back(t);
    }
  }
  std::string error;
  if (!builder.InitializeTensorProduct(degree, breaks, 1, &error))
  {
    return nullptr;
  }
  builder.SetCoefficientsFromGreville(
    [sharpness](const double g[3], double* c)
    {
      const double a[3] = { g[0] - 0.35, g[1] - 0.4, g[2] - 0.45 };
      const double b[3] = { g[0] - 0.7, g[1] - 0.65, g[2] - 0.6 };
      c[0] = std::exp(-(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * sharpness / 0.08) +
        0.8 * std::exp(-(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]) * sharpness / 0.04) + 0.2 * g[2];
    });
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  const double focus[2][3] = { { 0.35, 0.4, 0.45 }, { 0.7, 0.65, 0.6 } };
  for (int l = 0; l < levels; ++l)
  {
    for (const auto& f : focus)
    {
      if (!builder.RefineAt(f, l % 2 ? golden : 0.5, &error))
      {
        return nullptr;
      }
    }
  }
  {
    std::ofstream out(path);
    builder.GetPatch().Write(out);
  }
  if (elements)
  {
    *elements = builder.GetNumberOfElements();
  }
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetOutputFieldName("density");
  reader->Update();
  return reader->GetOutput();
}

/// The volume tests' transfer functions over the scalar range [a, b]: blue,
/// cyan, yellow and red, the middle two at the fractions `cyan` and `yellow`
/// of the range, and the opacity linear between `opacity`'s (fraction,
/// opacity) points (fraction 0 is a, 1 is b).
inline void SetTransferFunctions(vtkVolumeProperty* property, double a, double b,
  double cyan = 0.35, double yellow = 0.65,
  const std::vector<std::array<double, 2>>& opacity = {
    { 0.0, 0.0 }, { 0.3, 0.05 }, { 0.6, 0.5 }, { 1.0, 0.9 } })
{
  const double w = b - a;
  auto at = [a, b, w](double fraction) { return fraction == 1.0 ? b : a + fraction * w; };
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(a, 0.05, 0.15, 0.9);
  ctf->AddRGBPoint(at(cyan), 0.1, 0.8, 0.9);
  ctf->AddRGBPoint(at(yellow), 0.95, 0.9, 0.2);
  ctf->AddRGBPoint(b, 0.9, 0.1, 0.05);
  vtkNew<vtkPiecewiseFunction> otf;
  for (const auto& point : opacity)
  {
    otf->AddPoint(at(point[0]), point[1]);
  }
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
}

/// A window of width x height (no multisampling) whose renderer, of the given
/// background, shows `mapper` with `property` as Volume.
struct Scene
{
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  Scene(vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* property, int width, int height,
    const double background[3])
  {
    this->Volume->SetMapper(mapper);
    this->Volume->SetProperty(property);
    this->Renderer->SetBackground(background[0], background[1], background[2]);
    this->Renderer->AddVolume(this->Volume);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
  }

  /// The camera: reset to `bounds` (nullptr: the visible props'), turned by
  /// `azimuth` and `elevation` (degrees), reset again and zoomed by `zoom`.
  void SetCamera(const double* bounds, double azimuth, double elevation, double zoom)
  {
    auto reset = [&]()
    {
      if (bounds)
      {
        this->Renderer->ResetCamera(bounds);
      }
      else
      {
        this->Renderer->ResetCamera();
      }
    };
    reset();
    this->Renderer->GetActiveCamera()->Azimuth(azimuth);
    this->Renderer->GetActiveCamera()->Elevation(elevation);
    reset();
    this->Renderer->GetActiveCamera()->Zoom(zoom);
  }
};

/// A smooth bend of the unit cube (not affine; injective for these
/// amplitudes): the curved geometry of the tests.
inline void Bend(const double x[3], double y[3])
{
  const double pi = 3.14159265358979323846;
  y[0] = x[0] + 0.12 * std::sin(pi * x[1]) * std::sin(pi * x[2]);
  y[1] = x[1] + 0.10 * std::sin(pi * x[0]) + 0.05 * x[2] * x[2];
  y[2] = x[2] + 0.08 * std::sin(2 * pi * x[0]) * x[1];
}

/// The LRSplines volume text `text` with every basis function's coefficient
/// c (3 values) replaced by the `dimension` values v that `coefficient(c, v)`
/// gives; with `weight` (a rational spline), by the homogeneous coefficients
/// (w v, w), w = weight() per basis function. The spline's own coefficients
/// are changed, so that multi-patch volumes stay conforming.
inline std::string RewriteCoefficients(const std::string& text, int dimension,
  const std::function<void(const double c[3], double* v)>& coefficient,
  const std::function<double()>& weight = nullptr)
{
  std::istringstream in(text);
  std::ostringstream out;
  out.precision(17);
  std::string line;
  bool header = false;
  while (std::getline(in, line))
  {
    if (line.find("# LRSPLINE") == 0)
    {
      header = true;
      out << line << "\n";
      continue;
    }
    if (header && !line.empty() && line[0] != '#')
    {
      // p1 p2 p3 Nbasis Nline Nel dim rat
      std::istringstream h(line);
      int v[8];
      for (int& x : v)
      {
        h >> x;
      }
      v[6] = dimension + (weight ? 1 : 0);
      for (int i = 0; i < 8; ++i)
      {
        out << v[i] << (i < 7 ? " " : "\n");
      }
      header = false;
      continue;
    }
    const auto close = line.rfind(']');
    const auto paren = line.rfind('(');
    if (line.find(": [") != std::string::npos && close != std::string::npos &&
      paren != std::string::npos && paren > close)
    {
      std::istringstream c(line.substr(close + 1, paren - close - 1));
      double x[3];
      c >> x[0] >> x[1] >> x[2];
      std::vector<double> v(static_cast<std::size_t>(dimension));
      coefficient(x, v.data());
      const double w = weight ? weight() : 1.0;
      out << line.substr(0, close + 1);
      for (double y : v)
      {
        out << " " << w * y;
      }
      if (weight)
      {
        out << " " << w;
      }
      out << " " << line.substr(paren) << "\n";
      continue;
    }
    out << line << "\n";
  }
  return out.str();
}

/// The smallest element side (data units) of a field.
inline double MinimumElementSide(const vtkLRSplineField& field)
{
  double m = 1e300;
  for (int p = 0; p < field.GetNumberOfPatches(); ++p)
  {
    const auto& patch = field.GetPatch(p);
    for (vtkIdType e = 0; e < patch.GetNumberOfElements(); ++e)
    {
      m = std::min(m, patch.GetElementMinimumSide(e));
    }
  }
  return m;
}
}

#endif
