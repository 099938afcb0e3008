// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __merl_nearest__: the nearest-bin lookup of merl_eval, compiled.  The bin
// of each direction pair is the MERL reference reader's bin.  A fast path
// computes the half vector and the difference vector with square roots (no
// trigonometric rotation) and finds the bins by comparing cos theta_h,
// cos theta_d and the phi_d direction with tables of the bin edges (no acos,
// no atan2).  A sample within 1e-6 (in index units) of a bin edge, with the
// half vector along the normal (theta_h < 1e-6: phi_h is the atan2 of
// rounding residues) or wi close to wo (theta_d < 1e-5: so is phi_d) is
// placed with the reader's own sequence of operations (its two Rodrigues
// rotations, term by term, as inst/merl/private/merl_index_ref.m), written here
// from the published formulas.  Built with -ffp-contract=off (src/Makefile)
// so that no multiply-add is fused: every operation of that path rounds as
// Octave's element-wise operations do.

#include <octave/oct.h>

#include "oct_guard.h"

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace
{
  const double PI = 3.14159265358979323846;   // == Octave's pi
  const octave_idx_type NBINS = 90 * 90 * 180;

  // v rotated about the unit axis a by angle ang (Rodrigues), in the order
  // of operations of the reference reader.
  inline void
  rodrigues (double vx, double vy, double vz, double ax, double ay, double az,
             double ang, double& ox, double& oy, double& oz)
  {
    const double c = std::cos (ang);
    const double s = std::sin (ang);
    ox = vx * c; oy = vy * c; oz = vz * c;
    double t = ax * vx + ay * vy + az * vz;
    t = t * (1.0 - c);
    ox += ax * t; oy += ay * t; oz += az * t;
    const double cx = ay * vz - az * vy;
    const double cy = az * vx - ax * vz;
    const double cz = ax * vy - ay * vx;
    ox += cx * s; oy += cy * s; oz += cz * s;
  }

  // An index from a real number: truncated toward zero, clamped to
  // [0, hi]; NaN gives 0 (what the reader's int conversion gives on x86).
  inline int
  clamp_fix (double x, int hi)
  {
    if (! (x >= 0))
      return 0;
    if (x >= hi)
      return hi;
    return static_cast<int> (x);
  }

  // 0-based bin with the reference reader's arithmetic.
  inline octave_idx_type
  index_ref (const double *wi, const double *wo)
  {
    double hx = (wi[0] + wo[0]) / 2;
    double hy = (wi[1] + wo[1]) / 2;
    double hz = (wi[2] + wo[2]) / 2;
    const double len = std::sqrt (hx * hx + hy * hy + hz * hz);
    hx /= len; hy /= len; hz /= len;
    const double th = std::acos (hz);
    const double ph = std::atan2 (hy, hx);
    double tx, ty, tz, dx, dy, dz;
    rodrigues (wi[0], wi[1], wi[2], 0, 0, 1, -ph, tx, ty, tz);
    rodrigues (tx, ty, tz, 0, 1, 0, -th, dx, dy, dz);
    const double td = std::acos (dz);
    double pd = std::atan2 (dy, dx);
    int ih = 0;
    if (th > 0)
      {
        const double t = ((th / (PI / 2.0)) * 90) * 90;
        ih = clamp_fix (std::sqrt (t), 89);
      }
    const int id = clamp_fix (td / (PI * 0.5) * 90, 89);
    if (pd < 0)
      pd += PI;
    const int ip = clamp_fix (pd / PI * 360 / 2, 179);
    return ip + id * 180 + ih * 180 * 90;
  }

  // The bin edges as thresholds, so that the fast path needs no acos or
  // atan2.  theta_h: edge k (1..89) at th_k = (k/90)^2 pi/2, where
  // cos (theta_h) = CH[k]; theta_d: edge k at k degrees, cos = CD[k];
  // phi_d: edge k (0..180) at k degrees, direction (CP[k], SP[k]).  Each
  // edge has a margin: MARGIN index units, converted to the compared
  // quantity (TH[k], TD[k] in cosine, MP in radians).  A sample within the
  // margin of an edge goes to index_ref.  Guess tables give the bin at the
  // low end of a cell of a cheap monotone function of the quantity; a step
  // or two along the thresholds then finds the bin.
  const double MARGIN = 1e-6;
  const int NG = 1024;

  struct edges
  {
    double CH[91], TH[91], CD[91], TD[91], CP[181], SP[181], MP;
    double h_small, d_small;
    unsigned char gh[NG + 1], gd[NG + 1], gp[NG + 1];

    edges ()
    {
      const double deg = PI / 180;
      for (int k = 0; k <= 90; k++)
        {
          const double th = (k / 90.0) * (k / 90.0) * (PI / 2);
          CH[k] = std::cos (th);
          // d ch / d th = 8100 / (pi/2) / (2 ch) at ch = k
          TH[k] = k == 0 ? 0 : std::sin (th) * MARGIN * (2.0 * k * (PI / 2) / 8100);
          CD[k] = std::cos (k * deg);
          TD[k] = std::sin (k * deg) * MARGIN * deg;
        }
      for (int k = 0; k <= 180; k++)
        {
          CP[k] = std::cos (k * deg);
          SP[k] = std::sin (k * deg);
        }
      MP = std::sin (MARGIN * deg);
      h_small = std::cos (1e-6);
      d_small = std::cos (1e-5);
      for (int c = 0; c <= NG; c++)
        {
          const double q = double (c) / NG;
          // theta_h: cell of sqrt (sqrt (1 - cos th))
          const double th = std::acos (1 - q * q * q * q);
          gh[c] = std::min (89, int (std::sqrt (th / (PI / 2)) * 90));
          // theta_d: cell of sqrt (1 - cos td)
          const double td = std::acos (std::max (1 - q * q, -1.0));
          gd[c] = std::min (89, int (td / deg));
          // phi_d: cell of the pseudo-angle p = 1 - x / (|x| + y), in [0, 2]
          const double x = 1 - 2 * q;
          const double ps = std::atan2 (1 - std::abs (x), x);
          gp[c] = std::min (179, int (ps / deg));
        }
    }
  };

  const edges&
  the_edges ()
  {
    static const edges e;     // built once (thread-safe in C++11)
    return e;
  }

  inline int
  cell (double v)
  {
    // v in [0, 1]; NaN and out-of-range values are clamped
    if (! (v > 0))
      return 0;
    if (v >= 1)
      return NG;
    return int (v * NG);
  }

  // 0-based bin: the fast path, or index_ref where rounding decides.  The
  // fast path's half and difference vectors are accurate to a few units in
  // the last place; it decides a bin only when the sample is more than
  // MARGIN (1e-6 index units) from every bin edge, far outside that error.
  // theta_h < 1e-6 and theta_d < 1e-5 go to the reader's arithmetic too,
  // because there phi_h or phi_d is the atan2 of rounding residues, which
  // only the reader's own operations reproduce.
  inline octave_idx_type
  index_fast (const double *wi, const double *wo, const edges& e)
  {
    const double hx = wi[0] + wo[0];
    const double hy = wi[1] + wo[1];
    double hz = wi[2] + wo[2];
    const double rxy = hx * hx + hy * hy;
    const double inv = 1 / std::sqrt (rxy + hz * hz);
    hz *= inv;
    if (! (hz <= e.h_small && rxy > 0))      // also NaN
      return index_ref (wi, wo);
    const double sth = std::sqrt (rxy) * inv;
    const double r = 1 / std::sqrt (rxy);
    const double cph = hx * r;
    const double sph = hy * r;
    const double x1 = wi[0] * cph + wi[1] * sph;
    const double y1 = wi[1] * cph - wi[0] * sph;
    const double x2 = x1 * hz - wi[2] * sth;
    const double z2 = x1 * sth + wi[2] * hz;
    if (! (z2 <= e.d_small))
      return index_ref (wi, wo);
    // theta_h: CH[g] >= hz > CH[g+1]
    int ih = e.gh[cell (std::sqrt (std::sqrt (1 - hz)))];
    while (ih < 89 && hz <= e.CH[ih + 1])
      ih++;
    while (ih > 0 && hz > e.CH[ih])
      ih--;
    if ((ih > 0 && e.CH[ih] - hz < e.TH[ih])
        || (ih < 89 && hz - e.CH[ih + 1] < e.TH[ih + 1]))
      return index_ref (wi, wo);
    // theta_d: CD[g] >= z2 > CD[g+1]
    int id = e.gd[cell (std::sqrt (1 - z2))];
    while (id < 89 && z2 <= e.CD[id + 1])
      id++;
    while (id > 0 && z2 > e.CD[id])
      id--;
    if ((id > 0 && e.CD[id] - z2 < e.TD[id])
        || (id < 89 && z2 - e.CD[id + 1] < e.TD[id + 1]))
      return index_ref (wi, wo);
    // phi_d = atan2 (y1, x2) folded into [0, pi): the direction (x, y),
    // y >= 0; near 0 or pi (y small) the fold itself is decided by signs
    // of rounding residues
    double x = x2, y = y1;
    if (y < 0)
      {
        x = -x;
        y = -y;
      }
    const double rv = std::sqrt (x * x + y * y);
    const double tol = rv * e.MP;
    if (! (y > tol))
      return index_ref (wi, wo);
    int ip = e.gp[cell ((1 - x / (std::abs (x) + y)) / 2)];
    // angle >= k degrees <=> CP[k] y - SP[k] x >= 0
    while (ip < 179 && e.CP[ip + 1] * y - e.SP[ip + 1] * x >= 0)
      ip++;
    while (ip > 0 && e.CP[ip] * y - e.SP[ip] * x < 0)
      ip--;
    if ((ip > 0 && e.CP[ip] * y - e.SP[ip] * x < tol)
        || (ip < 179 && e.SP[ip + 1] * x - e.CP[ip + 1] * y < tol))
      return index_ref (wi, wo);
    return (octave_idx_type (ih) * 90 + id) * 180 + ip;
  }

  struct lookup_job
  {
    const double *wi, *wo, *data;
    const bool *valid;
    double *rgb, *idx;
    bool *ok;
    octave_idx_type n;
    bool ref;
  };

  // Samples [lo, hi) of the job, in blocks: first the bins of a block (the
  // arithmetic), then its values (independent loads from the 35 MB table,
  // which the processor overlaps; interleaved with the arithmetic they
  // would wait on each other).  Directions are rows of N x 3 column-major
  // arrays.
  void
  run (const lookup_job& j, octave_idx_type lo, octave_idx_type hi)
  {
    const octave_idx_type n = j.n;
    const octave_idx_type B = 1024;
    octave_idx_type bin[B];
    const edges& e = the_edges ();
    for (octave_idx_type k0 = lo; k0 < hi; k0 += B)
      {
        const octave_idx_type m = std::min (B, hi - k0);
        for (octave_idx_type q = 0; q < m; q++)
          {
            const octave_idx_type k = k0 + q;
            const double a[3] = {j.wi[k], j.wi[k + n], j.wi[k + 2 * n]};
            const double b[3] = {j.wo[k], j.wo[k + n], j.wo[k + 2 * n]};
            if (a[2] > 0 && b[2] > 0)
              bin[q] = j.ref ? index_ref (a, b) : index_fast (a, b, e);
            else
              bin[q] = -1;
          }
        for (octave_idx_type q = 0; q < m; q++)
          {
            const octave_idx_type k = k0 + q;
            const octave_idx_type i = bin[q];
            const bool ok = i >= 0 && j.valid[i];
            if (ok)
              {
                j.rgb[k] = j.data[i];
                j.rgb[k + n] = j.data[i + NBINS];
                j.rgb[k + 2 * n] = j.data[i + 2 * NBINS];
              }
            else
              j.rgb[k] = j.rgb[k + n] = j.rgb[k + 2 * n] = 0;
            if (j.ok)
              j.ok[k] = ok;
            if (j.idx)
              j.idx[k] = double (i + 1);
          }
      }
  }

  bool
  is_dirs (const octave_value& v)
  {
    return v.is_double_type () && v.isreal () && ! v.issparse ()
           && v.ndims () == 2 && v.columns () == 3;
  }
}

DEFUN_DLD (__merl_nearest__, args, nargout,
           R"doc(-*- texinfo -*-
@deftypefn  {} {[@var{rgb}, @var{valid}, @var{idx}] =} __merl_nearest__ (@var{data}, @var{ok}, @var{wi}, @var{wo})
@deftypefnx {} {[@dots{}] =} __merl_nearest__ (@var{data}, @var{ok}, @var{wi}, @var{wo}, @var{method})
Nearest-bin lookup of a MERL table (internal; use @code{merl_eval}).

@var{data} is the 1458000 x 3 double table and @var{ok} the 1458000 x 1
logical mask of a MERL struct; @var{wi}, @var{wo} are N x 3 double unit
directions (only their shape is checked here: @code{merl_eval} checks that
they are unit vectors; other values give some bin or 0, never a crash).  @var{rgb} (N x 3)
is the bin's value, 0 below the horizon or for a missing sample;
@var{valid} (N x 1 logical) says which samples have a value; @var{idx}
(N x 1) is the 1-based bin, 0 below the horizon.

@var{method} @qcode{"fast"} (default) compares the half and difference
vectors with tables of the bin edges and places the samples within 1e-6 of
a bin edge with the reference reader's arithmetic; @qcode{"ref"} uses the reader's arithmetic
(two Rodrigues rotations with sines and cosines) for every sample: the same
bins, slower (the peer of @code{scripts/bench_merl.m}).

Errors: @code{lafortune:badInput}, @code{lafortune:outOfMemory}.

@example
@group
b = merl_standin ("red-plastic");
rgb = __merl_nearest__ (b.data, b.valid, [0 0 1], [0 0.6 0.8])
@end group
@end example
@seealso{merl_eval}
@end deftypefn)doc")
{
  const int nargin = args.length ();
  if (nargin < 4 || nargin > 5)
    print_usage ();
  const octave_value& D = args(0);
  const octave_value& V = args(1);
  if (! (D.is_double_type () && D.isreal () && ! D.issparse () && D.ndims () == 2
         && D.rows () == NBINS && D.columns () == 3))
    error_with_id ("lafortune:badInput",
                   "__merl_nearest__: DATA must be a real %ld x 3 double array",
                   static_cast<long> (NBINS));
  if (! (V.islogical () && ! V.issparse () && V.ndims () == 2 && V.rows () == NBINS
         && V.columns () == 1))
    error_with_id ("lafortune:badInput",
                   "__merl_nearest__: OK must be a %ld x 1 logical array",
                   static_cast<long> (NBINS));
  if (! is_dirs (args(2)) || ! is_dirs (args(3)) || args(2).rows () != args(3).rows ())
    error_with_id ("lafortune:badInput",
                   "__merl_nearest__: WI and WO must be real N x 3 double arrays with the same N");
  bool ref = false;
  if (nargin > 4)
    {
      std::string m;
      if (args(4).is_string ())
        m = args(4).string_value ();
      if (m == "ref")
        ref = true;
      else if (m != "fast")
        error_with_id ("lafortune:badInput",
                       "__merl_nearest__: METHOD must be \"fast\" or \"ref\"");
    }
  const NDArray data = D.array_value ();
  const boolNDArray valid = V.bool_array_value ();
  const NDArray wi = args(2).array_value ();
  const NDArray wo = args(3).array_value ();
  const octave_idx_type n = wi.rows ();

  octave_value_list retval (nargout > 1 ? (nargout > 2 ? 3 : 2) : 1);
  oct_guard ("__merl_nearest__", [&] ()
    {
      NDArray rgb (dim_vector (n, 3));
      boolNDArray ok (dim_vector (nargout > 1 ? n : 0, 1));
      NDArray idx (dim_vector (nargout > 2 ? n : 0, 1));
      lookup_job j;
      j.wi = wi.data ();
      j.wo = wo.data ();
      j.data = data.data ();
      j.valid = valid.data ();
      j.rgb = rgb.fortran_vec ();
      j.ok = nargout > 1 ? ok.fortran_vec () : nullptr;
      j.idx = nargout > 2 ? idx.fortran_vec () : nullptr;
      j.n = n;
      j.ref = ref;
      run (j, 0, n);
      retval(0) = rgb;
      if (nargout > 1)
        retval(1) = ok;
      if (nargout > 2)
        retval(2) = idx;
    });
  return retval;
}

/*
%!shared b, wi, wo
%! b.data = repmat ((1:1458000)', 1, 3);
%! b.valid = true (1458000, 1);
%! rand ("state", 7);
%! n = 20000;
%! u = rand (n, 2); v = rand (n, 2);
%! wi = [sqrt(1 - u(:,1).^2) .* cos(2*pi*u(:,2)), sqrt(1 - u(:,1).^2) .* sin(2*pi*u(:,2)), u(:,1)];
%! wo = [sqrt(1 - v(:,1).^2) .* cos(2*pi*v(:,2)), sqrt(1 - v(:,1).^2) .* sin(2*pi*v(:,2)), v(:,1)];

%!test
%! ## the fast path and the reader's arithmetic give the same bins
%! [r1, ok1, i1] = __merl_nearest__ (b.data, b.valid, wi, wo);
%! [r2, ok2, i2] = __merl_nearest__ (b.data, b.valid, wi, wo, "ref");
%! assert (i1, i2);
%! assert (r1(:,1), i1);
%! assert (all (ok1) && all (ok2));

%!test
%! ## on bin edges, where rounding decides: directions built from the bins'
%! ## own angles (theta_h on its sqrt grid, theta_d and phi_d on theirs)
%! [ih, id, ip] = ndgrid ([0 1 2 10 45 88 89], [0 1 30 60 89], [0 1 45 90 179]);
%! th = (ih(:) / 90) .^ 2 * pi / 2; td = id(:) / 90 * pi / 2; pd = ip(:) / 180 * pi;
%! d = [sin(td).*cos(pd) sin(td).*sin(pd) cos(td)];
%! wi = [d(:,1).*cos(th) + d(:,3).*sin(th), d(:,2), -d(:,1).*sin(th) + d(:,3).*cos(th)];
%! wo = [-d(:,1).*cos(th) + d(:,3).*sin(th), -d(:,2), d(:,1).*sin(th) + d(:,3).*cos(th)];
%! wi ./= sqrt (sum (wi .^ 2, 2)); wo ./= sqrt (sum (wo .^ 2, 2));
%! up = wi(:,3) > 0 & wo(:,3) > 0;
%! [~, ~, i1] = __merl_nearest__ (b.data, b.valid, wi, wo);
%! [~, ~, i2] = __merl_nearest__ (b.data, b.valid, wi, wo, "ref");
%! assert (i1, i2);
%! assert (nnz (up) > 100);
%! assert (all (i1(up) >= 1));
%! assert (all (i1(! up) == 0));

%!test
%! ## below the horizon and missing samples: 0, not valid
%! b2 = b; b2.valid(1) = false;
%! [rgb, ok, idx] = __merl_nearest__ (b2.data, b2.valid, [0 0 1; 0 0 1; 0 0.6 0.8], [0 0 1; 0 0.6 -0.8; 0 0 -1]);
%! assert (idx, [1; 0; 0]);
%! assert (rgb, zeros (3, 3));
%! assert (ok, [false; false; false]);
%! [rgb, ok] = __merl_nearest__ (b2.data, b2.valid, zeros (0, 3), zeros (0, 3));
%! assert (size (rgb), [0 3]);
%! assert (size (ok), [0 1]);

%!test
%! ## directions that are not unit vectors (merl_eval rejects them) give a
%! ## bin in range or 0, never a read outside the table
%! w = [NaN 0 1; 0 0 Inf; 0 0 0; 1e300 1e300 1; -Inf 0 1; 0 0 1e-300; 3 4 5];
%! [i, j] = ndgrid (1:rows (w));
%! [rgb, ok, idx] = __merl_nearest__ (b.data, b.valid, w(i(:),:), w(j(:),:));
%! assert (all (idx >= 0 & idx <= 1458000));
%! assert (rgb(:,1), idx);
%! assert (ok, idx > 0);

%!error <Invalid call> __merl_nearest__ (1, 2, 3)
%!error id=lafortune:badInput __merl_nearest__ (zeros (10, 3), true (1458000, 1), [0 0 1], [0 0 1])
%!error id=lafortune:badInput __merl_nearest__ (single (zeros (1458000, 3)), true (1458000, 1), [0 0 1], [0 0 1])
%!error id=lafortune:badInput __merl_nearest__ (zeros (1458000, 3), ones (1458000, 1), [0 0 1], [0 0 1])
%!error id=lafortune:badInput __merl_nearest__ (zeros (1458000, 3), true (1458000, 1), [0 0 1 0], [0 0 1])
%!error id=lafortune:badInput __merl_nearest__ (zeros (1458000, 3), true (1458000, 1), [0 0 1; 0 0 1], [0 0 1])
%!error id=lafortune:badInput __merl_nearest__ (zeros (1458000, 3), true (1458000, 1), single ([0 0 1]), [0 0 1])
%!error id=lafortune:badInput __merl_nearest__ (zeros (1458000, 3), true (1458000, 1), [0 0 1], [0 0 1], "cubic")
%!error id=lafortune:badInput __merl_nearest__ (zeros (1458000, 3), true (1458000, 1), [0 0 1], [0 0 1], 3)
*/
