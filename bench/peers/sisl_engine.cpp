#include <chrono>
#include <cmath>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfReal.hxx>

#include "peer_engines.hpp"

extern "C" {
#include <sisl.h>
}

namespace peers {

using namespace ssimarch;

namespace {

// An OpenCASCADE B-spline surface as a SISL one (non-periodic; rational as homogeneous
// coefficients (w x, w y, w z, w), the first parameter running fastest).
SISLSurf* to_sisl(const Handle(Geom_Surface)& s) {
  Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(s->Copy());
  if (b.IsNull()) return nullptr;
  if (b->IsUPeriodic()) b->SetUNotPeriodic();
  if (b->IsVPeriodic()) b->SetVNotPeriodic();
  const int nu = b->NbUPoles(), nv = b->NbVPoles(), ku = b->UDegree() + 1, kv = b->VDegree() + 1;
  std::vector<double> tu(nu + ku), tv(nv + kv), coef;
  TColStd_Array1OfReal fu(1, nu + ku), fv(1, nv + kv);
  b->UKnotSequence(fu);
  b->VKnotSequence(fv);
  for (int i = 0; i < nu + ku; ++i) tu[i] = fu(i + 1);
  for (int j = 0; j < nv + kv; ++j) tv[j] = fv(j + 1);
  const bool rational = b->IsURational() || b->IsVRational();
  for (int j = 1; j <= nv; ++j)
    for (int i = 1; i <= nu; ++i) {
      const gp_Pnt p = b->Pole(i, j);
      const double w = rational ? b->Weight(i, j) : 1.0;
      coef.insert(coef.end(), {w * p.X(), w * p.Y(), w * p.Z()});
      if (rational) coef.push_back(w);
    }
  return newSurf(nu, nv, ku, kv, tu.data(), tv.data(), coef.data(), rational ? 2 : 1, 3, 1);
}

// Length and residual of a SISL curve by 400 evaluations (the length as the polyline's).
void measure(SISLCurve* c, const Surface& a, const Surface& b, Outcome* out) {
  const double t0 = c->et[c->ik - 1], t1 = c->et[c->in];
  int left = 0, stat = 0;
  double prev[3] = {0, 0, 0}, p[3];
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    s1221(c, 0, t0 + (t1 - t0) * k / n, &left, p, &stat);
    if (k > 0) out->length += std::sqrt((p[0] - prev[0]) * (p[0] - prev[0]) + (p[1] - prev[1]) * (p[1] - prev[1]) + (p[2] - prev[2]) * (p[2] - prev[2]));
    out->residual = std::max(out->residual, residual(a, b, Vec3(p[0], p[1], p[2])));
    std::copy(p, p + 3, prev);
  }
}

}  // namespace

namespace {

Outcome sisl_in_process(const OcctPair& pair, const Surface& a, const Surface& b, double* ms) {
  Outcome out;
  *ms = NAN;
  SISLSurf* s1 = pair.first.IsNull() ? nullptr : to_sisl(pair.first);
  SISLSurf* s2 = pair.second.IsNull() ? nullptr : to_sisl(pair.second);
  if (!s1 || !s2) {
    out.note = "no B-spline pair";
    return out;
  }
  int npt = 0, ncrv = 0, stat = 0;
  double *par1 = nullptr, *par2 = nullptr;
  SISLIntcurve** curves = nullptr;
  const auto t0 = std::chrono::steady_clock::now();
  s1859(s1, s2, 1e-15, 1e-7, &npt, &par1, &par2, &ncrv, &curves, &stat);
  for (int i = 0; i < ncrv && stat >= 0; ++i) s1310(s1, s2, curves[i], 1e-7, 0.0, 1, 0, &stat);
  *ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (stat < 0) out.note = "status " + std::to_string(stat);
  out.curves = ncrv;
  out.isolated = npt;
  for (int i = 0; i < ncrv; ++i) {
    if (curves[i]->itype == 2 || curves[i]->itype == 3) ++out.closed;
    if (curves[i]->pgeom) measure(curves[i]->pgeom, a, b, &out);
  }
  if (curves) freeIntcrvlist(curves, ncrv);
  free(par1);
  free(par2);
  freeSurf(s1);
  freeSurf(s2);
  return out;
}

}  // namespace

// SISL's subdivision can run for minutes on a singular case: it runs in a child process that is
// killed after kSislSeconds (the outcome then says so).
constexpr unsigned kSislSeconds = 20;

Outcome run_sisl(const OcctPair& pair, const Surface& a, const Surface& b, double* ms) {
  int fd[2];
  if (pipe(fd) != 0) return sisl_in_process(pair, a, b, ms);
  const pid_t child = fork();
  if (child == 0) {
    close(fd[0]);
    alarm(kSislSeconds);
    double t = NAN;
    const Outcome o = sisl_in_process(pair, a, b, &t);
    const double nums[6] = {t, double(o.curves), double(o.isolated), double(o.closed), o.length, o.residual};
    if (write(fd[1], nums, sizeof nums) != static_cast<ssize_t>(sizeof nums)) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  double nums[6];
  const bool got = read(fd[0], nums, sizeof nums) == static_cast<ssize_t>(sizeof nums);
  close(fd[0]);
  waitpid(child, nullptr, 0);
  Outcome out;
  *ms = NAN;
  if (!got) {
    out.note = "killed after " + std::to_string(kSislSeconds) + " s";
    return out;
  }
  *ms = nums[0];
  out.curves = int(nums[1]);
  out.isolated = int(nums[2]);
  out.closed = int(nums[3]);
  out.length = nums[4];
  out.residual = nums[5];
  return out;
}

}  // namespace peers
