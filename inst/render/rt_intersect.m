## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{hit} =} rt_intersect (@var{objects}, @var{O}, @var{D})
## @deftypefnx {lafortune} {@var{hit} =} rt_intersect (@var{objects}, @var{O}, @var{D}, @var{tmin}, @var{tmax})
## @deftypefnx {lafortune} {@var{hit} =} rt_intersect (@var{objects}, @var{O}, @var{D}, @var{tmin}, @var{tmax}, @var{anyhit})
## @deftypefnx {lafortune} {@var{hit} =} rt_intersect (@var{objects}, @var{O}, @var{D}, @var{tmin}, @var{tmax}, @var{anyhit}, @var{engine})
## Intersect rays with the objects of a scene, vectorised over the rays.
##
## @var{objects} is the struct array @code{scene.objects} of
## @code{scene_make} (spheres, planes, triangle meshes).  A mesh object may
## carry a field @code{bvh} from @code{rt_bvh}; without it the hierarchy is
## built on each call (@code{rt_render} builds it once).  @var{O} and
## @var{D} are N x 3 ray origins and unit directions.  Hits count for
## @var{tmin} < t < @var{tmax} (scalars or N x 1; defaults 0 and Inf).
##
## @var{hit} is a struct of N x 1 arrays: @code{t} (distance, Inf for a
## miss), @code{obj} (object index, 0 for a miss), @code{prim} (triangle
## index for meshes, else 0), @code{u}, @code{v} (barycentric coordinates of
## the hit in the triangle: P = (1-u-v) A + u B + v C).  With @var{anyhit}
## true (shadow rays), the search stops at the first hit found: @code{t} is
## finite exactly for the rays that hit something, but not necessarily the
## nearest hit.
##
## Meshes are traversed by @var{engine}:
##
## @table @code
## @item "compiled"
## the oct-file @code{__rt_traverse__} (@file{src/}, built by
## @code{pkg install}): one ray at a time, depth first with a small stack,
## near child first, boxes entered beyond the ray's best hit so far skipped,
## the triangles of the leaves tested (Moeller-Trumbore).  Meshes of more
## than 2048 triangles are traced by one thread per core (at most 16).
## @item "octave"
## the same tests in Octave, vectorised: a stack of (ray, node) pairs
## processed in waves; each wave pops the most recently pushed pairs (so each
## ray goes roughly depth first, near child first), culls pairs whose box
## entry lies beyond the ray's best hit so far, tests the triangles of the
## leaves and pushes the children whose boxes are hit.  Slower (make bench's
## bench_render says by how much).
## @item "auto"
## (default) "compiled" when the oct-file exists, else "octave".
## @end table
##
## Both give the same nearest hits; where two triangles are hit at exactly the
## same distance (a ray through a shared edge) either may be reported.
## Spheres are hit by the oct-file @code{__rt_sphere__} when it is built,
## unless @var{engine} is @qcode{"octave"}: the same arithmetic as the
## Octave code, bit for bit.
##
## @example
## @group
## s = scene_make ("spheres");
## O = [0 5 0; 0 5 0]; D = [0 -1 0; 1 0 0];
## hit = rt_intersect (s.objects, O, D);
## [hit.t hit.obj]
## @end group
## @end example
## @seealso{rt_bvh, rt_render, scene_make}
## @end deftypefn

function hit = rt_intersect (objects, O, D, tmin, tmax, anyhit, engine)
  if (nargin < 3 || nargin > 7)
    print_usage ();
  endif
  if (! isstruct (objects) || ! isfield (objects, "type"))
    error ("lafortune:badScene", "rt_intersect: OBJECTS must be the struct array scene.objects");
  endif
  if (! (isnumeric (O) && isnumeric (D) && isreal (O) && isreal (D) && ndims (O) == 2
         && ndims (D) == 2 && columns (O) == 3 && columns (D) == 3 && rows (O) == rows (D)))
    error ("lafortune:badInput", "rt_intersect: O and D must be real N x 3 arrays of the same size");
  endif
  n = rows (O);
  O = full (double (O));
  D = full (double (D));
  if (nargin < 4 || isempty (tmin))
    tmin = 0;
  endif
  if (nargin < 5 || isempty (tmax))
    tmax = Inf;
  endif
  if (nargin < 6 || isempty (anyhit))
    anyhit = false;
  endif
  if (! (isscalar (anyhit) && (islogical (anyhit) || isnumeric (anyhit))))
    error ("lafortune:badInput", "rt_intersect: ANYHIT must be true or false");
  endif
  anyhit = logical (anyhit);
  if (nargin < 7)
    engine = "auto";
  endif
  if (! ischar (engine) || ! any (strcmp (engine, {"auto", "compiled", "octave"})))
    error ("lafortune:badOption",
           "rt_intersect: ENGINE must be \"auto\", \"compiled\" or \"octave\"");
  endif
  have_oct = exist ("__rt_traverse__", "file") == 3;
  if (strcmp (engine, "compiled") && ! have_oct)
    error ("lafortune:noOctFile",
           "rt_intersect: the oct-file __rt_traverse__ is missing (run make -C src, or pkg install the package)");
  endif
  compiled = have_oct && ! strcmp (engine, "octave");
  if (! (isnumeric (tmin) && isreal (tmin) && any (numel (tmin) == [1 n])
         && isnumeric (tmax) && isreal (tmax) && any (numel (tmax) == [1 n])))
    error ("lafortune:badInput", "rt_intersect: TMIN and TMAX must be real scalars or N x 1");
  endif
  tmin = double (full (tmin(:))) .* ones (n, 1);
  tbest = double (full (tmax(:))) .* ones (n, 1);
  hit.t = Inf (n, 1);
  hit.obj = zeros (n, 1);
  hit.prim = zeros (n, 1);
  hit.u = zeros (n, 1);
  hit.v = zeros (n, 1);
  todo = (1:n).';
  for k = 1:numel (objects)
    if (anyhit)
      todo = todo(! isfinite (hit.t(todo)));
      if (isempty (todo))
        break;
      endif
    endif
    ob = objects(k);
    if (numel (todo) == n)               # every ray (no copies)
      o = O;
      d = D;
      tb = tbest;
      t0 = tmin;
    else
      o = O(todo,:);
      d = D(todo,:);
      tb = tbest(todo);
      t0 = tmin(todo);
    endif
    switch (ob.type)
      case "sphere"
        ## the oct-file __rt_sphere__ makes the same operations, compiled
        done = false;
        if (! strcmp (engine, "octave") && isa (ob.center, "double") && isa (ob.radius, "double"))
          [done, t, ok] = __lafortune_oct_call__ ("__rt_sphere__", "rt_intersect", o, d,
                                                  ob.center(:).', ob.radius ^ 2, t0, tb);
        endif
        if (! done)
          oc = o - ob.center(:).';
          b = sum (oc .* d, 2);
          disc = b .^ 2 - (sum (oc .^ 2, 2) - ob.radius ^ 2);
          sq = sqrt (max (disc, 0));
          t = -b - sq;
          back = t <= t0;
          t(back) = -b(back) + sq(back);
          ok = disc >= 0 & t > t0 & t < tb;
        endif
        pr = 0; u = 0; v = 0;
      case "plane"
        nrm = ob.normal(:).';
        den = d * nrm.';
        t = ((ob.point(:).' - o) * nrm.') ./ den;
        ok = den != 0 & t > t0 & t < tb;
        pr = 0; u = 0; v = 0;
      case "mesh"
        if (isfield (ob, "bvh") && ! isempty (ob.bvh))
          bvh = ob.bvh;
        else
          bvh = rt_bvh (ob.vertices, ob.faces);
        endif
        done = false;
        if (compiled && isfield (bvh, "boxes"))
          nthr = 1;
          if (rows (ob.faces) > 2048 && rows (o) >= 2048)
            nthr = min (nproc (), 16);      # one thread per core
          endif
          ## (a built oct-file that does not load warns there, once)
          [done, t, pr, u, v] = __lafortune_oct_call__ ("__rt_traverse__", "rt_intersect",
                                                        bvh.boxes, bvh.tris, bvh.tri, bvh.nleaf,
                                                        o, d, t0, tb, anyhit, nthr);
        endif
        if (! done)
          [t, pr, u, v] = mesh_hit (bvh, o, d, t0, tb, anyhit);
        endif
        ok = t < tb;
        pr = pr(ok); u = u(ok); v = v(ok);
      otherwise
        error ("lafortune:badScene",
               "rt_intersect: unknown object type '%s' (expected sphere, plane or mesh)",
               ob.type);
    endswitch
    i = todo(ok);
    tk = t(ok);
    hit.t(i) = tk;
    tbest(i) = tk;
    hit.obj(i) = k;
    if (k > 1 || ! isequal (pr, 0) || ! isequal (u, 0) || ! isequal (v, 0))
      hit.prim(i) = pr;                  # (the first object's zeros are there)
      hit.u(i) = u;
      hit.v(i) = v;
    endif
  endfor
endfunction

## Nearest (or any) hit of rays with a BVH mesh, in Octave (engine
## "octave").  T is Inf where nothing is hit before TBEST.
function [t, prim, bu, bv] = mesh_hit (b, O, D, tmin, tbest, anyhit)
  n = rows (O);
  tmax = tbest;
  invD = 1 ./ D;
  prim = zeros (n, 1);
  bu = zeros (n, 1);
  bv = zeros (n, 1);
  found = false (n, 1);
  t_any = zeros (n, 1);
  r = (1:n).';
  [tn, h] = box_test (b, ones (n, 1), r, O, invD, tmin, tbest);
  cap = max (4 * n, 1024);
  sr = zeros (cap, 1);
  sn = zeros (cap, 1);
  st = zeros (cap, 1);
  top = nnz (h);
  sr(1:top) = r(h);
  sn(1:top) = 1;
  st(1:top) = tn(h);
  wave = max (n, 4096);
  L = b.slots;
  while (top > 0)
    k = min (wave, top);
    idx = (top-k+1:top).';
    r = sr(idx);
    nd = sn(idx);
    live = st(idx) <= tbest(r);
    top -= k;
    r = r(live);
    nd = nd(live);
    isleaf = nd >= b.nleaf;
    if (any (isleaf))
      rl = r(isleaf);
      s = (nd(isleaf) - b.nleaf) * L + (1:L);      # pairs x L slots
      rr = repmat (rl, 1, L)(:);
      s = s(:);
      d = D(rr,:);
      e1 = b.e1(s,:);
      e2 = b.e2(s,:);
      tv = O(rr,:) - b.v0(s,:);
      p = [d(:,2).*e2(:,3) - d(:,3).*e2(:,2), d(:,3).*e2(:,1) - d(:,1).*e2(:,3), ...
           d(:,1).*e2(:,2) - d(:,2).*e2(:,1)];
      idet = 1 ./ sum (e1 .* p, 2);
      u = sum (tv .* p, 2) .* idet;
      q = [tv(:,2).*e1(:,3) - tv(:,3).*e1(:,2), tv(:,3).*e1(:,1) - tv(:,1).*e1(:,3), ...
           tv(:,1).*e1(:,2) - tv(:,2).*e1(:,1)];
      v = sum (d .* q, 2) .* idet;
      tt = sum (e2 .* q, 2) .* idet;
      ok = u >= 0 & v >= 0 & u + v <= 1 & tt > tmin(rr) & tt < tbest(rr);
      if (any (ok))
        rr = rr(ok); tt = tt(ok); s = s(ok); u = u(ok); v = v(ok);
        if (anyhit)
          found(rr) = true;
          tbest(rr) = -Inf;
          prim(rr) = b.tri(s);
          bu(rr) = u;
          bv(rr) = v;
          t_any(rr) = tt;
        else
          [~, o] = sort (tt, "descend");   # the last (nearest) write wins
          tbest(rr(o)) = tt(o);
          w = tt == tbest(rr);
          prim(rr(w)) = b.tri(s(w));
          bu(rr(w)) = u(w);
          bv(rr(w)) = v(w);
          found(rr) = true;
        endif
      endif
    endif
    ri = r(! isleaf);
    if (! isempty (ri))
      c = 2 * nd(! isleaf);
      m = numel (ri);
      [tc, hc] = box_test (b, [c; c+1], [ri; ri], O, invD, tmin, tbest);
      t1 = tc(1:m); t2 = tc(m+1:end);
      h1 = hc(1:m); h2 = hc(m+1:end);
      both = h1 & h2;
      n1 = t1 <= t2;
      ## far children first, near ones on top of the stack
      f1 = both & ! n1;                     # child 1 is the far one
      f2 = both & n1;
      p1 = h1 & ! f1;
      p2 = h2 & ! f2;
      pr = [ri(f1); ri(f2); ri(p1); ri(p2)];
      pn = [c(f1); c(f2)+1; c(p1); c(p2)+1];
      pt = [t1(f1); t2(f2); t1(p1); t2(p2)];
      np = numel (pr);
      if (top + np > cap)
        cap = max (2 * cap, top + np);
        sr(cap) = 0; sn(cap) = 0; st(cap) = 0;
      endif
      sr(top+1:top+np) = pr;
      sn(top+1:top+np) = pn;
      st(top+1:top+np) = pt;
      top += np;
    endif
  endwhile
  t = Inf (n, 1);
  if (anyhit)
    t(found) = t_any(found);
  else
    t(found) = tbest(found);
  endif
endfunction

function [tn, h] = box_test (b, nodes, r, O, invD, tmin, tbest)
  o = O(r,:);
  id = invD(r,:);
  t1 = (b.bmin(nodes,:) - o) .* id;
  t2 = (b.bmax(nodes,:) - o) .* id;
  tn = max (max (min (t1, t2), [], 2), tmin(r));
  tf = min (min (max (t1, t2), [], 2), tbest(r));
  h = tn <= tf;
endfunction

%!function [t, tri] = brute (V, F, O, D)
%!  ## reference: every ray against every triangle, one at a time
%!  n = rows (O);
%!  t = Inf (n, 1); tri = zeros (n, 1);
%!  for i = 1:n
%!    for j = 1:rows (F)
%!      A = V(F(j,1),:); B = V(F(j,2),:); C = V(F(j,3),:);
%!      M = [-D(i,:)', (B - A)', (C - A)'];
%!      if (abs (det (M)) < 1e-14), continue; endif
%!      x = M \ (O(i,:) - A)';
%!      if (x(2) >= 0 && x(3) >= 0 && x(2) + x(3) <= 1 && x(1) > 0 && x(1) < t(i))
%!        t(i) = x(1); tri(i) = j;
%!      endif
%!    endfor
%!  endfor
%!endfunction

%!test
%! ## a small mesh against a brute-force loop over all triangles, both engines
%! [V, F] = mesh_torus ([14 7]);
%! V = V * [1 0 0; 0 0.6 -0.8; 0 0.8 0.6];
%! rand ("state", 3); randn ("state", 3);
%! n = 300;
%! O = [4 * rand(n, 2) - 2, 3 * ones(n, 1)];
%! O(1:100,:) = 0.3 * randn (100, 3);     # some rays start inside the hole
%! D = [0.3 * randn(n, 2), -ones(n, 1)];
%! D(1:100,:) = randn (100, 3);
%! D(101:110,:) = repmat ([0 0 -1], 10, 1);  # axis-parallel rays
%! D ./= sqrt (sum (D .^ 2, 2));
%! obj = struct ("type", "mesh", "center", [], "radius", [], "point", [], ...
%!               "normal", [], "vertices", V, "faces", F, "normals", []);
%! [t, tri] = brute (V, F, O, D);
%! assert (nnz (isfinite (t)) > 50);
%! h = find (isfinite (t));
%! ts = sort (t(isfinite (t)));
%! tm = (ts(30) + ts(31)) / 2;
%! hits = {};
%! for engine = {"octave", "compiled"}
%!   obj.bvh = [];
%!   hit = rt_intersect (obj, O, D, 0, Inf, false, engine{1});
%!   assert (isfinite (hit.t), isfinite (t));
%!   assert (hit.t, t, 1e-9);
%!   assert (hit.prim, tri);
%!   assert (hit.obj, double (isfinite (t)));
%!   ## barycentrics give the hit point
%!   P = (1 - hit.u(h) - hit.v(h)) .* V(F(tri(h),1),:) + hit.u(h) .* V(F(tri(h),2),:) ...
%!       + hit.v(h) .* V(F(tri(h),3),:);
%!   assert (P, O(h,:) + t(h) .* D(h,:), 1e-9);
%!   ## leaf size 1 (deep tree), tmax and any-hit
%!   obj.bvh = rt_bvh (V, F, 1);
%!   hit1 = rt_intersect (obj, O, D, 0, tm, false, engine{1});
%!   e = t; e(t >= tm) = Inf;
%!   assert (hit1.t, e, 1e-9);
%!   hita = rt_intersect (obj, O, D, 0, Inf, true, engine{1});
%!   assert (isfinite (hita.t), isfinite (t));
%!   assert (all (hita.t(h) >= t(h) - 1e-9));
%!   hits{end+1} = hit;
%! endfor
%! ## the two engines: the same nearest hits, bit for bit
%! assert (isequal (hits{1}, hits{2}));
%! ## the default engine is the compiled one
%! obj.bvh = [];
%! assert (isequal (rt_intersect (obj, O, D), hits{2}));

%!test
%! ## spheres and planes: analytic distances, nearest object wins
%! s = scene_make ("spheres");
%! O = [-1.6 5 -0.2; 0 5 3; 0 5 3; 10 0.5 0.5];
%! D = [0 -1 0; 0 -1 0; 0 1 0; -1 0 0];
%! hit = rt_intersect (s.objects, O, D);
%! assert (hit.t, [5 - 1.4; 5; Inf; 10 - 1.7 - 0.5], 1e-12);
%! assert (hit.obj, [2; 1; 0; 4]);
%! ## rays starting inside a sphere hit its far side; tmin skips the start
%! hit = rt_intersect (s.objects(2), [-1.6 0.7 -0.2], [1 0 0]);
%! assert (hit.t, 0.7, 1e-12);
%! hit = rt_intersect (s.objects(2), [-2.3 0.7 -0.2], [1 0 0], 1e-9);
%! assert (hit.t, 1.4, 1e-12);
%! ## any-hit: blocked or not
%! hit = rt_intersect (s.objects, [-1.6 2 -0.2; 5 5 5], [0 -1 0; 0 1 0], 0, Inf, true);
%! assert (isfinite (hit.t), [true; false]);

%!test
%! ## spheres: the compiled hits (__rt_sphere__) and engine "octave"'s, bit
%! ## for bit, nearest and any hits, from outside and inside, with bounds
%! s = scene_make ("spheres");
%! rand ("state", 7);
%! n = 4000;
%! O = randn (n, 3) * 2; D = randn (n, 3); D ./= sqrt (sum (D .^ 2, 2));
%! tm = 1 + 5 * rand (n, 1);
%! for any = [false true]
%!   a = rt_intersect (s.objects, O, D, 1e-9, tm, any);
%!   b = rt_intersect (s.objects, O, D, 1e-9, tm, any, "octave");
%!   assert (isequal (a, b));
%!   assert (nnz (isfinite (a.t)) > 100);
%! endfor

%!error <Invalid call> rt_intersect (1, 2)
%!error id=lafortune:badScene rt_intersect (1, [0 0 0], [0 0 1])
%!error id=lafortune:badInput rt_intersect (struct ("type", "sphere"), [0 0], [0 0 1])
%!error id=lafortune:badInput rt_intersect (struct ("type", "sphere"), [0 0 0], [0 0 1], 0, Inf, "yes")
%!error id=lafortune:badInput rt_intersect (struct ("type", "sphere"), [0 0 1i], [0 0 1])
%!error id=lafortune:badInput rt_intersect (struct ("type", "sphere"), [0 0 0; 1 1 1], [0 0 1; 0 0 1], [0 0 0])
%!error id=lafortune:badOption rt_intersect (struct ("type", "sphere"), [0 0 0], [0 0 1], 0, Inf, false, "fast")
