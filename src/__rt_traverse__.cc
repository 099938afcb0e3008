// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __rt_traverse__: rays against the bounding volume hierarchy of rt_bvh,
// compiled.  The same tests as rt_intersect's Octave traversal: slab test of
// the node boxes, Moeller-Trumbore per triangle slot with its order of
// operations, a hit counts for tmin < t < tbest and 0 <= u, 0 <= v,
// u + v <= 1; children nearest first.  One ray at a time, depth first, with
// a small stack.  (Where a ray runs exactly in the plane of a box face, the
// Octave traversal's 0 * Inf = NaN makes it miss the box; here it touches
// it, which can only cost time, never a hit.)

#include <octave/oct.h>

#include "oct_guard.h"

#include <cmath>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <thread>
#include <vector>

namespace
{
  struct tree
  {
    const double *box;      // 6 x nnode: bmin (3), bmax (3) per node
    const double *tri9;     // 9 x nslot: v0, e1, e2 per slot
    const double *tri;      // nslot: triangle index, 0 = empty slot
    octave_idx_type nleaf, slots;
  };

  struct rays
  {
    const double *O, *D, *tmin, *tmax;
    octave_idx_type n;
    bool anyhit;
    double *t, *prim, *u, *v;
  };

  // The slab test of the box of node k (1-based): entry distance TN, and
  // whether the ray enters the box before it leaves it and before TBEST.
  // SGN[a] is 1 where the ray's direction is negative, so the near and far
  // planes are known without a min or max per axis; ID is finite (see
  // trace), so no 0 * Inf makes a NaN, and the maxima and minima compile
  // without branches.
  inline bool
  box_hit (const tree& b, octave_idx_type k, const double o[3], const double id[3],
           const int sgn[3], double t0, double tbest, double& tn)
  {
    const double *bx = b.box + 6 * (k - 1);
    double lo = t0, hi = tbest;
    for (int a = 0; a < 3; a++)
      {
        const double tnear = (bx[a + 3 * sgn[a]] - o[a]) * id[a];
        const double tfar = (bx[a + 3 - 3 * sgn[a]] - o[a]) * id[a];
        lo = tnear > lo ? tnear : lo;
        hi = tfar < hi ? tfar : hi;
      }
    tn = lo;
    return lo <= hi && lo < std::numeric_limits<double>::infinity ();
  }

  void
  trace (const tree& b, const rays& r, octave_idx_type lo, octave_idx_type hi)
  {
    const octave_idx_type n = r.n;
    const double inf = std::numeric_limits<double>::infinity ();
    octave_idx_type stk_node[256];
    double stk_t[256];
    for (octave_idx_type i = lo; i < hi; i++)
      {
        const double o[3] = {r.O[i], r.O[i + n], r.O[i + 2 * n]};
        const double d[3] = {r.D[i], r.D[i + n], r.D[i + 2 * n]};
        // 1/d, with +-1e308 for +-0: a ray parallel to a slab is inside it
        // or outside it, also when it lies on the slab's plane (a touch
        // counts; a box test may only be generous, never miss a triangle)
        double id[3];
        int sgn[3];
        for (int a = 0; a < 3; a++)
          {
            id[a] = 1 / d[a];
            if (std::isinf (id[a]))
              id[a] = std::copysign (1e308, id[a]);
            sgn[a] = id[a] < 0;
          }
        const double t0 = r.tmin[i];
        double tbest = r.tmax[i];
        bool found = false;
        double bt = inf, bp = 0, bu = 0, bv = 0;
        int top = 0;
        double tn;
        if (box_hit (b, 1, o, id, sgn, t0, tbest, tn))
          {
            stk_node[0] = 1;
            stk_t[0] = tn;
            top = 1;
          }
        while (top > 0)
          {
            top--;
            const octave_idx_type k = stk_node[top];
            if (! (stk_t[top] <= tbest))
              continue;
            if (k >= b.nleaf)
              {
                const octave_idx_type s0 = (k - b.nleaf) * b.slots;
                for (octave_idx_type s = s0; s < s0 + b.slots; s++)
                  {
                    if (b.tri[s] == 0)
                      continue;
                    const double *g = b.tri9 + 9 * s;
                    const double *e1 = g + 3, *e2 = g + 6;
                    const double tv[3] = {o[0] - g[0], o[1] - g[1], o[2] - g[2]};
                    const double p[3] = {d[1] * e2[2] - d[2] * e2[1],
                                         d[2] * e2[0] - d[0] * e2[2],
                                         d[0] * e2[1] - d[1] * e2[0]};
                    const double idet = 1 / (e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2]);
                    const double u = (tv[0] * p[0] + tv[1] * p[1] + tv[2] * p[2]) * idet;
                    if (! (u >= 0))
                      continue;
                    const double q[3] = {tv[1] * e1[2] - tv[2] * e1[1],
                                         tv[2] * e1[0] - tv[0] * e1[2],
                                         tv[0] * e1[1] - tv[1] * e1[0]};
                    const double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) * idet;
                    if (! (v >= 0 && u + v <= 1))
                      continue;
                    const double tt = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * idet;
                    if (tt > t0 && tt < tbest)
                      {
                        found = true;
                        tbest = tt;
                        bt = tt;
                        bp = b.tri[s];
                        bu = u;
                        bv = v;
                        if (r.anyhit)
                          break;
                      }
                  }
                if (found && r.anyhit)
                  break;
              }
            else
              {
                const octave_idx_type c = 2 * k;
                double ta, tb;
                const bool ha = box_hit (b, c, o, id, sgn, t0, tbest, ta);
                const bool hb = box_hit (b, c + 1, o, id, sgn, t0, tbest, tb);
                // the far child first, the near one on top
                if (ha && hb)
                  {
                    if (ta <= tb)
                      {
                        stk_node[top] = c + 1; stk_t[top++] = tb;
                        stk_node[top] = c; stk_t[top++] = ta;
                      }
                    else
                      {
                        stk_node[top] = c; stk_t[top++] = ta;
                        stk_node[top] = c + 1; stk_t[top++] = tb;
                      }
                  }
                else if (ha)
                  {
                    stk_node[top] = c; stk_t[top++] = ta;
                  }
                else if (hb)
                  {
                    stk_node[top] = c + 1; stk_t[top++] = tb;
                  }
              }
          }
        r.t[i] = found ? bt : inf;
        r.prim[i] = bp;
        r.u[i] = bu;
        r.v[i] = bv;
      }
  }

  bool
  real_double (const octave_value& a)
  {
    return a.is_double_type () && a.isreal () && ! a.issparse () && a.ndims () == 2;
  }
}

DEFUN_DLD (__rt_traverse__, args, ,
           R"doc(-*- texinfo -*-
@deftypefn  {} {[@var{t}, @var{prim}, @var{u}, @var{v}] =} __rt_traverse__ (@var{boxes}, @var{tris}, @var{tri}, @var{nleaf}, @var{O}, @var{D}, @var{tmin}, @var{tmax}, @var{anyhit})
@deftypefnx {} {[@dots{}] =} __rt_traverse__ (@dots{}, @var{threads})
Rays against the triangles of a BVH from @code{rt_bvh} (internal; use
@code{rt_intersect}).

@var{boxes} (6 x (2 @var{nleaf} - 1)), @var{tris} (9 x @var{nleaf} L) and
@var{tri} (@var{nleaf} L x 1) are the fields @code{boxes}, @code{tris} and
@code{tri} of the BVH, @var{nleaf} its field @code{nleaf} (a power of two).
@var{O}, @var{D} are N x 3 ray origins and directions, @var{tmin} and
@var{tmax} N x 1; a hit counts for @var{tmin} < t < @var{tmax}.  @var{t}
is the nearest hit's distance (Inf for none), @var{prim} its triangle (0 for
none), @var{u}, @var{v} its barycentric coordinates.  With @var{anyhit}
true a ray stops at the first hit found.  @var{threads} (default 1, at most
64) splits the rays over that many threads.

Errors: @code{lafortune:badInput}, @code{lafortune:outOfMemory}.

@example
@group
b = rt_bvh ([0 0 0; 1 0 0; 0 1 0], [1 2 3]);
[t, prim] = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, [0.2 0.2 1], [0 0 -1], 0, Inf, false)
@end group
@end example
@seealso{rt_intersect, rt_bvh}
@end deftypefn)doc")
{
  const int nargin = args.length ();
  if (nargin < 9 || nargin > 10)
    print_usage ();
  const octave_value& BX = args(0);
  const octave_value& TR = args(1);
  const octave_value& TI = args(2);
  if (! (args(3).isnumeric () && args(3).isreal () && args(3).numel () == 1))
    error_with_id ("lafortune:badInput", "__rt_traverse__: NLEAF must be a power of two");
  const double nl = args(3).double_value ();
  if (! (nl >= 1 && nl <= 1073741824.0 && nl == std::floor (nl)
         && (static_cast<long> (nl) & (static_cast<long> (nl) - 1)) == 0))
    error_with_id ("lafortune:badInput", "__rt_traverse__: NLEAF must be a power of two");
  const octave_idx_type nleaf = static_cast<octave_idx_type> (nl);
  if (! (real_double (BX) && BX.rows () == 6 && BX.columns () == 2 * nleaf - 1))
    error_with_id ("lafortune:badInput",
                   "__rt_traverse__: BOXES must be a real 6 x %ld double array",
                   static_cast<long> (2 * nleaf - 1));
  if (! (real_double (TR) && TR.rows () == 9 && TR.columns () >= nleaf
         && TR.columns () % nleaf == 0))
    error_with_id ("lafortune:badInput",
                   "__rt_traverse__: TRIS must be a real 9 x (NLEAF*L) double array");
  const octave_idx_type nslot = TR.columns ();
  if (! (real_double (TI) && TI.numel () == nslot))
    error_with_id ("lafortune:badInput",
                   "__rt_traverse__: TRI must be a real double array of %ld slots",
                   static_cast<long> (nslot));
  const octave_value& Ov = args(4);
  const octave_value& Dv = args(5);
  if (! (real_double (Ov) && real_double (Dv) && Ov.columns () == 3 && Dv.columns () == 3
         && Ov.rows () == Dv.rows ()))
    error_with_id ("lafortune:badInput",
                   "__rt_traverse__: O and D must be real N x 3 double arrays of the same size");
  const octave_idx_type n = Ov.rows ();
  if (! (real_double (args(6)) && real_double (args(7)) && args(6).numel () == n
         && args(7).numel () == n))
    error_with_id ("lafortune:badInput",
                   "__rt_traverse__: TMIN and TMAX must be real N x 1 double arrays");
  if (! (args(8).numel () == 1 && (args(8).islogical () || args(8).isnumeric ())))
    error_with_id ("lafortune:badInput", "__rt_traverse__: ANYHIT must be true or false");
  const bool anyhit = args(8).bool_value ();
  int nthr = 1;
  if (nargin > 9)
    {
      const octave_value& T = args(9);
      const double t = (T.isnumeric () && T.isreal () && T.numel () == 1)
                       ? T.double_value () : 0;
      if (! (t >= 1 && t <= 64 && t == std::floor (t)))
        error_with_id ("lafortune:badInput",
                       "__rt_traverse__: THREADS must be an integer from 1 to 64");
      nthr = static_cast<int> (t);
    }

  const NDArray boxes = BX.array_value ();
  const NDArray tris = TR.array_value ();
  const NDArray tri = TI.array_value ();
  const NDArray O = Ov.array_value ();
  const NDArray D = Dv.array_value ();
  const NDArray tmin = args(6).array_value ();
  const NDArray tmax = args(7).array_value ();

  octave_value_list retval (4);
  oct_guard ("__rt_traverse__", [&] ()
    {
      tree b;
      b.box = boxes.data ();
      b.tri9 = tris.data ();
      b.tri = tri.data ();
      b.nleaf = nleaf;
      b.slots = nslot / nleaf;
      NDArray t (dim_vector (n, 1)), prim (dim_vector (n, 1));
      NDArray u (dim_vector (n, 1)), v (dim_vector (n, 1));
      rays r;
      r.O = O.data ();
      r.D = D.data ();
      r.tmin = tmin.data ();
      r.tmax = tmax.data ();
      r.n = n;
      r.anyhit = anyhit;
      r.t = t.fortran_vec ();
      r.prim = prim.fortran_vec ();
      r.u = u.fortran_vec ();
      r.v = v.fortran_vec ();
      if (nthr > 1 && n >= 1024)
        {
          std::vector<std::thread> pool;
          std::vector<std::exception_ptr> fail (nthr);
          for (int k = 0; k < nthr; k++)
            {
              const octave_idx_type lo = n * k / nthr, hi = n * (k + 1) / nthr;
              pool.emplace_back ([&b, &r, &fail, k, lo, hi] ()
                {
                  try { trace (b, r, lo, hi); }
                  catch (...) { fail[k] = std::current_exception (); }
                });
            }
          for (auto& th : pool)
            th.join ();
          for (auto& f : fail)
            if (f)
              std::rethrow_exception (f);
        }
      else
        trace (b, r, 0, n);
      retval(0) = t;
      retval(1) = prim;
      retval(2) = u;
      retval(3) = v;
    });
  return retval;
}

/*
%!shared b
%! b = rt_bvh ([0 0 0; 1 0 0; 0 1 0; 1 1 0], [1 2 3; 2 4 3]);

%!test
%! ## two triangles of the unit square at z = 0, rays straight down
%! O = [0.2 0.2 1; 0.8 0.8 1; 2 2 1; 0.2 0.2 -1];
%! D = repmat ([0 0 -1], 4, 1);
%! [t, prim, u, v] = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, O, D, zeros (4, 1), Inf (4, 1), false);
%! assert (t, [1; 1; Inf; Inf]);
%! assert (prim, [1; 2; 0; 0]);
%! assert ([u(1) v(1)], [0.2 0.2], 1e-15);
%! ## tmax and tmin exclude the hit; any-hit finds it; two threads the same
%! t = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, O, D, zeros (4, 1), 0.5 * ones (4, 1), false);
%! assert (t, Inf (4, 1));
%! t = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, O, D, ones (4, 1), Inf (4, 1), false);
%! assert (t, Inf (4, 1));
%! t = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, O, D, zeros (4, 1), Inf (4, 1), true);
%! assert (isfinite (t), [true; true; false; false]);
%! O = repmat (O, 300, 1); D = repmat (D, 300, 1);
%! [t1, p1] = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, O, D, zeros (1200, 1), Inf (1200, 1), false);
%! [t2, p2] = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, O, D, zeros (1200, 1), Inf (1200, 1), false, 2);
%! assert (isequal (t1, t2) && isequal (p1, p2));
%! t = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, zeros (0, 3), zeros (0, 3), zeros (0, 1), zeros (0, 1), false);
%! assert (size (t), [0 1]);

%!test
%! ## NaN and Inf in rays never crash: they miss
%! O = [NaN 0 1; 0.2 0.2 Inf; 0.2 0.2 1];
%! D = [0 0 -1; 0 0 -1; NaN NaN NaN];
%! t = __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, O, D, zeros (3, 1), Inf (3, 1), false);
%! assert (t, Inf (3, 1));

%!error <Invalid call> __rt_traverse__ (1, 2, 3)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri, 3, [0 0 1], [0 0 -1], 0, Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri, 2 * b.nleaf, [0 0 1], [0 0 -1], 0, Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes(:,1:end-1), b.tris, b.tri, b.nleaf, [0 0 1], [0 0 -1], 0, Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris(1:8,:), b.tri, b.nleaf, [0 0 1], [0 0 -1], 0, Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri(1:end-1), b.nleaf, [0 0 1], [0 0 -1], 0, Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, [0 0 1 0], [0 0 -1], 0, Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, single ([0 0 1]), [0 0 -1], 0, Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, [0 0 1], [0 0 -1], [0 0], Inf, false)
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, [0 0 1], [0 0 -1], 0, Inf, "yes")
%!error id=lafortune:badInput __rt_traverse__ (b.boxes, b.tris, b.tri, b.nleaf, [0 0 1], [0 0 -1], 0, Inf, false, 0)
*/
