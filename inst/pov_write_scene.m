## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{info} =} pov_write_scene (@var{scene}, @var{material}, @var{file})
## @deftypefnx {lafortune} {@var{info} =} pov_write_scene (@dots{}, @var{name}, @var{value}, @dots{})
## Write a POV-Ray 3.7 scene that renders @var{scene} with @var{material}.
##
## The scene file has the camera, light, geometry and image size of the scene
## struct @var{scene} (from @code{scene_make}), so that POV-Ray renders
## pixel for pixel the image @code{rt_render} renders: the camera is written
## with explicit @code{direction}, @code{right} and @code{up} vectors in the
## scene's own right-handed, y-up coordinates (POV-Ray uses the vectors as
## given, so the image is not mirrored), and without anti-aliasing POV-Ray
## shoots one ray through each pixel centre, as @code{rt_render} does with
## @qcode{"jitter"}, false.
##
## @strong{How the surface shows the material.}  With a directional light
## (unit direction L) and an orthographic camera (unit direction V toward the
## viewer) the radiance of an isotropic BRDF depends only on
## ti = angle (N, L) and to = angle (N, V).  POV-Ray's @code{slope} pattern
## toward a direction d gives 1 - angle (N, d)/pi, so a pigment made of
## nested @code{pigment_map}s, @code{slope} toward L outside and toward V
## inside, is a table of colour over (ti, to) that POV-Ray interpolates
## bilinearly.  The tables come from @code{scene_slice} (the evaluation
## @code{rt_render} uses as well), as f(wi, wo) E = radiance / cos (ti): the
## surfaces have @code{finish @{ diffuse 1 ambient 0 emission 0 @}} and the
## light has colour 1, so POV-Ray itself multiplies by max (cos ti, 0) and
## leaves out what is in shadow.  (Emitting the whole radiance with
## @code{emission 1} would be simpler but emission is never shadowed: the
## spheres-on-a-plane scene would lose its cast shadows.)
##
## @strong{The inner angle.}  With an orthographic camera the inner maps
## are indexed by theta_h = angle (N, H) instead of to, with @code{slope}
## toward H = (L + V)/|L + V| (to follows from cos to = 2 cos theta_h
## cos (gamma/2) - cos ti).  Near the mirror direction a lobe depends on
## theta_h squared: over (ti, to) a lobe of exponent 1e5 is a sliver along
## the edge of what normals reach, which a map of 256 entries (POV-Ray's
## limit) misses, while over (ti, theta_h) it is a bump of the lobe's
## angular width.  Measured against @code{rt_render}'s per-sample shading
## at the pixel centres, a 256 x 256 sphere: 72.1 dB for e = 1e5 (54.9 dB
## over (ti, to), the highlight lost) and 88.8 dB for e = 2000 (75.3 dB); on
## the 26 measured materials of ../shared, the two renderers now agree on
## the fitted models to 58 dB or better (over (ti, to): down to 27 dB).
## (Lit from nearly behind the viewer, |L + V| < 0.1, and with a
## perspective camera the inner maps stay over to.)
##
## A Lafortune @var{material} gets one table per term: the diffuse term and
## each lobe, summed by an @code{average} pigment and @code{diffuse} @var{k}
## for @var{k} tables.  A MERL @var{material} gets one table.
##
## @strong{Where the entries go.}  Each table has its own entries, placed
## where its term bends, so a sharp lobe (exponents in the thousands) gets
## them around its peak and the diffuse term two per map.  The term is first
## tabulated densely (@qcode{"dense"} points per axis) on grids that are
## themselves refined twice toward where it bends (density proportional to
## the square root of the second derivative, plus an even share); the outer
## entries are then chosen from the dense ti by greedy refinement of the
## largest error of linear interpolation (weighted by cos ti, as the image
## is), and each inner map's entries likewise, independently, from the dense
## inner angle.  The error allowed, @qcode{"table_tol"} times the radiance
## level of the view (the 99th percentile of the material's radiance over
## the reached angles: relative to a measured material's specular peak,
## 1000 times the rest, the diffuse part was allowed errors of half its
## value), is shared between the tables in proportion to their size (flat
## tables need none) and split equally between the two levels; a map never
## has more than @qcode{"entries"} entries, so very sharp lobes may stop
## short of it (such a map starts from @qcode{"entries"}/4 evenly spaced
## entries, so that the peak does not take them all).
## Where no normal reaches (|ti - to| > gamma or ti + to < gamma, gamma the
## angle between L and V), @code{scene_slice} clamps to the nearest reachable
## configuration, which leaves a crease along the boundary (the specular
## peak lies on it); the tables instead continue each row linearly (in to)
## from the boundary, so that interpolation across it stays second-order
## accurate.
##
## @strong{What is left out.}  A lobe whose largest radiance anywhere the
## view reaches is below @qcode{"lobe_tol"} times the largest radiance of
## the whole material there is dropped.  The tables cover only the angles
## that visible, lit surfaces reach (outer map: the range of ti; each inner
## map: the range of the inner angle met near its ti), found by casting rays at every
## pixel centre, corner and edge midpoint (mesh vertices standing in for
## meshes), padded by @qcode{"pad"}; beyond its ends a @code{pigment_map}
## repeats its end entry.  Objects that are neither in the view nor able to
## cast a shadow on what is seen are left out, and so are such mesh faces
## (conservative bounding-box tests).
##
## Options:
## @table @asis
## @item @qcode{"entries"} (256)
## Largest number of entries in each map, 2 to 256 (POV-Ray's limit).
## @item @qcode{"knots"} (@qcode{"adaptive"})
## @qcode{"adaptive"}: as above; @qcode{"uniform"}: @qcode{"entries"}
## evenly spaced entries in every map (for comparison).
## @item @qcode{"table_tol"} (1e-3)
## Interpolation error allowed, relative to the radiance level of the view
## (see above).  0: fill every map to @qcode{"entries"}.  POV-Ray's OpenEXR
## output is half float (relative rounding 2.4e-4), so much less gains
## nothing.
## @item @qcode{"lobe_tol"} (1e-4)
## Lobes contributing less than this fraction of the largest radiance are
## dropped; 0 keeps every lobe.
## @item @qcode{"crop"} (true)
## Restrict the tables to the reached angles; false: ti in [0, pi/2], the
## inner angle in [0, pi/2] (to) or [0, pi] (theta_h).
## @item @qcode{"cull"} (true)
## Leave out objects and mesh faces outside the view that cast no shadow
## into it.
## @item @qcode{"pad"} (0.02)
## Margin in radians added around the reached angles.
## @item @qcode{"gamma_tol"} (0.03)
## Perspective camera: the error allowed when interpolating between levels
## of gamma, relative to the largest radiance (see above).
## @item @qcode{"dense"} (0: automatic)
## Points per axis of the dense tabulation the entries are chosen from;
## automatic is max (257, 2 @qcode{"entries"} + 1).
## @end table
##
## The file is written to a temporary file next to @var{file} and renamed.
## @var{info} has the fields @code{file}, @code{bytes}, @code{terms} (struct
## array: @code{name}, @code{contribution} (largest radiance relative to the
## whole), @code{kept}, @code{outer} (entries of the outer map),
## @code{inner} (entries of each inner map), @code{levels} (of gamma)),
## @code{entries} (all entries), @code{gamma} (the levels of gamma, one for
## an orthographic camera), @code{ti_range}, @code{to_range} (the range of
## the inner angle, theta_h or to, see above), @code{peak} (the largest
## radiance in the view), @code{level} (the radiance level the error
## allowed is relative to),
## @code{objects} (kept, logical), @code{faces_dropped}, @code{dense} and
## @code{time} (seconds).
##
## @strong{A perspective camera.}  The direction V toward the viewer then
## changes over the surfaces, and with it the angle gamma = angle (L, V), a
## third argument of the radiance.  POV-Ray's @code{aoi} pattern gives
## 1 - angle (N, ray)/pi for the camera ray (measured: the same convention
## as @code{slope}, to half-float precision), so it replaces the inner
## @code{slope} toward V; and a @code{function} pattern of the position,
## acos (L . (eye - P)/|eye - P|)/pi, indexes a third, outermost map whose
## entries are the (ti, to) tables at levels of gamma.  The levels cover only
## the range of gamma the lit visible points reach (a distant camera: a
## narrow range), and are halved where linear interpolation between two
## neighbouring levels of the whole material's slice is off by more than
## @qcode{"gamma_tol"} times its largest radiance (at most 64 levels).
## Each level is a table like the orthographic one, so the file grows with
## the number of levels (measured on 256 x 256 images, a 2-lobe model with
## exponents 40 and 5, against @code{rt_render}'s direct shading at the
## pixel centres: four spheres on a plane, 13 levels, 6.1 MB, 71 dB; the
## 100k-triangle Happy Buddha, 5 levels at @qcode{"gamma_tol"} 0.05, 6.3 MB,
## 55.6 dB).
##
## A point light (the angle to the light changes over the surfaces as well,
## a fourth table dimension) gives the error @code{lafortune:povUnsupported};
## @code{rt_render} renders it.
##
## @example
## @group
## scene = scene_make ("sphere");
## m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);
## info = pov_write_scene (scene, m, "sphere.pov");
## system ("povray +Isphere.pov +Osphere.exr +FE +W256 +H256 -A -D File_Gamma=1.0");
## @end group
## @end example
## @seealso{pov_render, scene_slice, rt_render, scene_make}
## @end deftypefn
function info = pov_write_scene (scene, material, file, varargin)
  if (nargin < 3)
    print_usage ();
  endif
  t0 = tic ();
  fname = "pov_write_scene";
  opt = parse_opts (varargin, fname,
                    struct ("entries", 256, "knots", "adaptive", "table_tol", 1e-3,
                            "lobe_tol", 1e-4, "crop", true, "cull", true, "pad", 0.02,
                            "dense", 0, "gamma_tol", 0.03));
  opt = check_opts (opt, fname);
  scene_check (scene, fname);
  cam = scene_camera (scene);
  kind = material_kind (material);
  if (isempty (kind))
    error ("lafortune:badMaterial",
           "%s: MATERIAL must be a Lafortune model or a MERL material, got %s",
           fname, class (material));
  endif
  light = scene.light;
  if (! strcmp (light.type, "directional"))
    error ("lafortune:povUnsupported",
           "%s: the tables need a directional light (then the shading depends on angle (N, L), angle (N, V) and angle (L, V) only), got a %s light; rt_render renders it",
           fname, light.type);
  endif
  persp = strcmp (cam.type, "perspective");
  if (! ischar (file) || isempty (file))
    error ("lafortune:badFile", "%s: FILE must be a non-empty string", fname);
  endif
  L = double (light.direction(:)');
  L /= norm (L);
  V = -cam.f;

  ## what the view reaches
  top = pi/2 - 1e-6;             # scene_slice is 0 from pi/2 on
  ## the inner maps' angle: theta_h = angle (N, H), H halfway between L and
  ## V, for an orthographic camera (a sharp lobe is a narrow bump in (ti,
  ## theta_h), but a thin sliver along the edge of what normals reach in
  ## (ti, to), where to grows as theta_h squared), else to
  C = inner_coord (persp, L, V);
  if (opt.crop || opt.cull || persp)     # the gamma levels need the points too
    S = pov_cast (scene, cam, L);
    S.u = inner_of (S.ti, S.to, C);
  endif
  if (opt.crop)
    if (isempty (S.ti))
      rng_i = [0 top];
      rng_o = [0 C.top];
    else
      rng_i = [max(0, min(S.ti) - opt.pad), min(top, max(S.ti) + opt.pad)];
      rng_o = [max(0, min(S.u) - opt.pad), min(C.top, max(S.u) + opt.pad)];
    endif
  else
    rng_i = [0 top];
    rng_o = [0 C.top];
  endif
  if (opt.cull)
    keep = S.keep;
    faces = S.faces;
  else
    keep = true (1, numel (scene.objects));
    faces = cell (1, numel (scene.objects));
  endif

  ## the terms, each tabulated densely by scene_slice
  if (strcmp (kind, "lafortune"))
    m = check_model (material, fname);
    terms = {};
    names = {};
    if (any (m.rho_d != 0))
      terms{end+1} = struct ("rho_d", m.rho_d, "Cxy", zeros (0, 3), "Cz", zeros (0, 3),
                             "e", zeros (0, 3));
      names{end+1} = "diffuse";
    endif
    for k = 1:rows (m.e)
      terms{end+1} = struct ("rho_d", [0 0 0], "Cxy", m.Cxy(k,:), "Cz", m.Cz(k,:),
                             "e", m.e(k,:));
      names{end+1} = sprintf ("lobe %d", k);
    endfor
  else
    terms = {material};
    names = {"measured"};
  endif
  n = opt.dense;
  if (n == 0)
    n = max (257, 2 * opt.entries + 1);
  endif
  ndense = n;
  if (opt.crop && ! isempty (S.ti))
    samp = [S.ti, S.u];
  else
    samp = [];
  endif
  ## the angle gamma between L and V: one value (orthographic), or levels
  ## over the range the visible points reach (perspective)
  if (persp)
    gl = gamma_levels (scene, material, L, S, rng_i, rng_o, opt);
  else
    gl = acos (max (min (L * V', 1), -1));
  endif
  ng = numel (gl);
  nt = numel (terms);
  D = cell (ng, nt);
  contrib = zeros (1, nt);
  peak = 0;
  level = 0;
  ## the whole material on a common grid, for its largest radiance
  t = linspace (rng_i(1), rng_i(2), 129);
  u = linspace (rng_o(1), rng_o(2), 129);
  reach = true;
  if (! isempty (samp))
    reach = reach_mask (samp, t', u', opt.pad);
  endif
  for g = 1:ng
    sg = view_at_gamma (scene, L, gl(g));
    for q = 1:nt
      D{g,q} = term_grid (sg, terms{q}, rng_i, rng_o, n, samp, opt, gl(g), C);
      contrib(q) = max (contrib(q), D{g,q}.max);
    endfor
    [lo, hi] = reach_bounds (t', gl(g), C);
    Mc = u >= lo & u <= hi & reach;
    Rc = slice_grid (sg, material, t, u, gl(g), C);
    peak = max ([peak, contrib, masked_max(Rc, Mc)]);
    level = max (level, masked_quantile (Rc, Mc, 0.99));
  endfor
  ## the error allowed is relative to the view's radiance level: its 99th
  ## percentile over the reached angles (a measured material's specular
  ## peak can be 1000 times the rest; relative to it, the diffuse part of
  ## the picture was allowed 45% errors)
  level = min (peak, level);
  if (! (level > 0))
    level = peak;
  endif
  if (peak > 0)
    contrib /= peak;
  endif
  kept = contrib > 0 & contrib >= opt.lobe_tol;
  if (strcmp (kind, "lafortune") && any (strcmp (names, "diffuse")))
    kept(1) = contrib(1) > 0;          # lobe_tol applies to lobes
  endif

  ## entries of each kept table; the error allowed is shared between the
  ## tables that are not flat (flat ones are exact), by their size, and
  ## between the two levels
  flat = all (cellfun (@(d) d.flat, D), 1);
  share = contrib .* kept .* ! flat;
  share /= max (sum (share), realmin);
  tabs = struct ("name", names, "contribution", num2cell (contrib), "kept", num2cell (kept),
                 "outer", 0, "inner", [], "levels", ng);
  body = {};
  for q = find (kept)
    tol = opt.table_tol * level * share(q) / 2;
    id = sprintf ("Lf_term%d", q);
    for g = 1:ng
      [sdl, no, ni] = term_sdl (D{g,q}, tol, peak, opt, L, C, names{q},
                                sprintf ("%s_%d", id, g), persp);
      D{g,q} = [];
      body{end+1} = sdl;
      tabs(q).outer += no;
      tabs(q).inner = [tabs(q).inner, ni];
    endfor
    if (persp)
      body{end+1} = gamma_sdl (id, names{q}, gl, cam.eye, L);
    else
      body{end+1} = sprintf ("#declare %s = pigment { %s_1 }\n", id, id);
    endif
  endfor

  ## write
  [osdl, nfd] = objects_sdl (scene.objects, keep, faces);
  parts = [{header_sdl(scene, material, opt, tabs, rng_i, rng_o, peak, C), camera_sdl(cam, scene), ...
            light_sdl(scene, L, cam)}, body, {texture_sdl(find (kept)), osdl}];
  atomic_write (file, fname, @(fid) write_text (fid, parts));
  d = dir (file);
  info = struct ("file", file, "bytes", d.bytes, "terms", tabs,
                 "entries", sum ([tabs.outer]) + sum ([tabs.inner]), "gamma", gl,
                 "ti_range", rng_i, "to_range", rng_o, "peak", peak, "level", level,
                 "objects", keep,
                 "faces_dropped", nfd, "dense", ndense, "time", toc (t0));
endfunction

## The knots and the SDL of one term's table at one gamma level: outer map
## over ti, inner maps over the inner angle (C); NO and NI count the entries.
function [sdl, no, ni] = term_sdl (Dq, tol, peak, opt, L, C, name, id, persp)
  ti = Dq.ti;
  to = Dq.to;
  T = Dq.T;
  Md = Dq.M;
  c = cos (ti);
  n = numel (ti);
  Ko = pov_knots (ti, reshape (T, n, 3 * n), c, repmat (Md, 1, 3), tol, opt.entries,
                  opt.knots);
  io = find (Ko);
  ## each inner table serves the ti between its neighbours
  lo = io([1 1:end-1]);
  hi = io([2:end end]);
  cs = [zeros(1, n); cumsum(Md, 1)];
  Mi = (cs(hi+1,:) - cs(lo,:))' > 0;                     # n x numel(io)
  G = permute (T(io,:,:), [2 3 1]);                      # n x 3 x numel(io)
  Ki = pov_knots (to, G, reshape (c(io), 1, 1, []), reshape (Mi, n, 1, []), tol,
                  opt.entries, opt.knots);
  no = numel (io);
  ni = sum (Ki, 1);
  T(abs (T) < 1e-12 * peak) = 0;     # no 1e-50s in the file
  if (persp)
    inner = "aoi";                   # 1 - angle (N, ray toward the eye)/pi
  else
    inner = sprintf ("slope { %s }", vec (C.dir));
  endif
  sdl = table_sdl (id, name, T, ti, to, io, Ki, L, inner);
endfunction

## Levels of gamma = angle (L, V) for a perspective camera: the range the
## lit visible samples reach (padded), cut until linear interpolation
## between neighbouring levels of the whole material's slice, on a 65 x 65
## grid over the reached (ti, to), is within table_tol/2 of its largest
## radiance (at most 64 levels).
function gl = gamma_levels (scene, material, L, S, rng_i, rng_o, opt)
  if (isempty (S.gamma))
    gl = [0; pi/2];
    return;
  endif
  g0 = max (0, min (S.gamma) - opt.pad);
  g1 = min (pi, max (S.gamma) + opt.pad);
  t = linspace (rng_i(1), rng_i(2), 65);
  u = linspace (rng_o(1), rng_o(2), 65);
  M = reach_mask ([S.ti, S.to], t', u', opt.pad);
  tab = @(g) masked (scene_slice (view_at_gamma (scene, L, g), material, t, u), M);
  gl = [g0; g1];
  R = {tab(g0), tab(g1)};
  peak = max ([R{1}(:); R{2}(:); realmin]);
  tol = opt.gamma_tol * peak;
  split = true;
  while (any (split) && numel (gl) < 64)
    split = false (numel (gl) - 1, 1);
    Rm = cell (1, numel (gl) - 1);
    for k = 1:numel (gl) - 1
      gm = (gl(k) + gl(k+1)) / 2;
      Rm{k} = tab (gm);
      err = max (abs (Rm{k}(:) - (R{k}(:) + R{k+1}(:)) / 2));
      split(k) = err > tol && gl(k+1) - gl(k) > 1e-4;
    endfor
    k = find (split);
    k = k(1:min (numel (k), 64 - numel (gl)));
    if (isempty (k))
      break;
    endif
    gn = (gl(k) + gl(k+1)) / 2;
    [gl, o] = sort ([gl; gn]);
    R = [R, Rm(k)](o);
  endwhile
endfunction

function R = masked (R, M)
  R = R .* M;
endfunction

## SCENE seen along a direction at the angle G from the light L (an
## orthographic view), for scene_slice
function sg = view_at_gamma (scene, L, g)
  p = null (L)(:,1)';
  Vg = cos (g) * L + sin (g) * p;
  sg = scene;
  sg.camera = struct ("type", "orthographic", "eye", Vg, "target", [0 0 0],
                      "up", null (Vg)(:,1)', "extent", 1, "fov", []);
endfunction

## the pigment ID of a term under a perspective camera: a function pattern
## of the position, gamma/pi = angle (L, eye - P)/pi, indexes its levels
function s = gamma_sdl (id, name, gl, eye, L)
  e = eye;
  fn = sprintf (["acos(min(1,max(-1,(%.12g*(%.12g-x)+%.12g*(%.12g-y)+%.12g*(%.12g-z))" ...
                 "/sqrt((%.12g-x)*(%.12g-x)+(%.12g-y)*(%.12g-y)+(%.12g-z)*(%.12g-z)+1e-30))))/pi"],
                L(1), e(1), L(2), e(2), L(3), e(3), e(1), e(1), e(2), e(2), e(3), e(3));
  s = sprintf ("// %s: %d levels of gamma = angle (L, V) from %.6g to %.6g rad\n#declare %s = pigment { function { %s } pigment_map {\n",
               name, numel (gl), gl(1), gl(end), id, fn);
  for g = 1:numel (gl)
    s = [s, sprintf("[%.9g %s_%d]\n", gl(g) / pi, id, g)];
  endfor
  s = [s, "} }\n"];
endfunction

function opt = check_opts (opt, fname)
  e = opt.entries;
  if (! isscalar (e) || ! isnumeric (e) || e != fix (e) || e < 2 || e > 256)
    error ("lafortune:badOption", "%s: \"entries\" must be an integer from 2 to 256", fname);
  endif
  if (! any (strcmp (opt.knots, {"adaptive", "uniform"})))
    error ("lafortune:badOption", "%s: \"knots\" must be \"adaptive\" or \"uniform\"", fname);
  endif
  for nm = {"table_tol", "lobe_tol", "pad", "gamma_tol"}
    v = opt.(nm{1});
    if (! isscalar (v) || ! isnumeric (v) || ! (v >= 0) || ! isfinite (v))
      error ("lafortune:badOption", "%s: \"%s\" must be a finite scalar >= 0", fname, nm{1});
    endif
  endfor
  for nm = {"crop", "cull"}
    v = opt.(nm{1});
    if (! isscalar (v) || ! (islogical (v) || isnumeric (v)))
      error ("lafortune:badOption", "%s: \"%s\" must be true or false", fname, nm{1});
    endif
    opt.(nm{1}) = logical (v);
  endfor
  d = opt.dense;
  if (! isscalar (d) || ! isnumeric (d) || d != fix (d) || (d != 0 && d < opt.entries))
    error ("lafortune:badOption", "%s: \"dense\" must be 0 (automatic) or an integer >= \"entries\"",
           fname);
  endif
endfunction

## Dense grids for one term, and its table on them.  The grids are not
## uniform: starting from a uniform one, twice, the term is tabulated and the
## points are redistributed along each axis with density proportional to the
## square root of the largest second derivative along it (the spacing that
## equalises the error of linear interpolation), plus a uniform share.  Sharp
## lobes thus get fine sampling around their peak.
function D = term_grid (scene, term, rng_i, rng_o, n, samp, opt, gam, C)
  passes = 2 * ! strcmp (opt.knots, "uniform");
  flat = false;
  n0 = n;
  if (passes)
    n0 = min (n, 129);                          # a coarse first look
  endif
  ti = linspace (rng_i(1), rng_i(2), n0)';
  to = linspace (rng_o(1), rng_o(2), n0)';
  for pass = 0:passes
    R = slice_grid (scene, term, ti, to, gam, C);
    c = cos (ti);
    [lo, hi] = reach_bounds (ti, gam, C);
    T = extend_c1 (R ./ c, ti, to, lo, hi,
                   @(t, p) slice_grid (scene, term, t, p, gam, C) / cos (t));
    ## what any normal can reach (the extension beyond it only serves the
    ## interpolation next to it), and with samples what the view reaches
    M = to' >= lo - opt.pad & to' <= hi + opt.pad;
    if (! isempty (samp))
      M &= reach_mask (samp, ti, to, opt.pad);
    endif
    if (pass == passes)
      break;
    endif
    G = T .* c;
    ki = curvature (ti, G, M);
    ko = curvature (to, permute (G, [2 1 3]), M');
    if (pass == 0 && ! any (ki > 1e-9 * max (abs (G(:)))) && ! any (ko > 1e-9 * max (abs (G(:)))))
      flat = true;                              # (a diffuse term): exact with 2
      break;                                    # entries, no refining

    endif
    nn = n;
    if (pass < passes - 1)
      nn = min (n, 257);                        # an intermediate look
    endif
    ti = regrid (ti, ki, nn);
    to = regrid (to, ko, nn);
  endfor
  D.flat = flat;
  D.ti = ti;
  D.to = to;
  ## the largest radiance where a normal really reaches (no padding): past
  ## the boundary scene_slice's clamped configurations are not the scene's
  ## and a sharp lobe may be huge there
  ## and what the view reaches: M (on this grid) has it
  [lo, hi] = reach_bounds (ti, gam, C);
  M0 = to' >= lo & to' <= hi;
  D.max = masked_max (R, M0 & M);
  ## the padding and the continuation only serve the interpolation: no entry
  ## above 10 times the term's largest radiance in the view (the file then
  ## holds no 1e130 where a lobe explodes past what the view reaches)
  T = min (T, 10 * D.max ./ max (cos (ti), 1e-3));
  D.T = T;
  D.M = M;
endfunction

## largest |second derivative| along dimension 1 of G over the masked columns
function k = curvature (x, G, M)
  n = numel (x);
  d = diff (G, 1, 1) ./ diff (x);
  k2 = abs (2 * diff (d, 1, 1) ./ (x(3:end) - x(1:end-2)));
  k2(! (M(2:end-1,:) & true (size (k2)))) = 0;
  k = max (reshape (permute (k2, [1 3 2]), n - 2, []), [], 2);
  k = [k(1); k; k(end)];
endfunction

function y = regrid (x, k, n)
  r = sqrt (k);
  w = min (5, numel (r));                       # widen the peaks a little
  rr = r;
  for s = 1:w
    rr(1+s:end) = max (rr(1+s:end), r(1:end-s));
    rr(1:end-s) = max (rr(1:end-s), r(1+s:end));
  endfor
  len = x(end) - x(1);
  tot = trapz (x, rr);
  if (! (tot > 0) || ! (len > 0))
    y = linspace (x(1), x(end), n)';
    return;
  endif
  rr += 0.3 * tot / len;                        # 23 % of the points uniform
  C = cumtrapz (x, rr);
  y = interp1 (C / C(end), x, linspace (0, 1, n)');
  y([1 end]) = x([1 end]);
endfunction

## reachable cells of the (ti, to) grid: for each ti row, the range of to of
## the samples within PAD of it, widened by PAD
function Md = reach_mask (samp, ti, to, pad)
  n = numel (ti);
  [sti, o] = sort (samp(:,1));
  sto = samp(o,2);
  a = lookup (sti, ti - pad) + 1;               # samples a:b lie within PAD
  b = lookup (sti, ti + pad);
  lo = inf (n, 1);
  hi = -inf (n, 1);
  for i = find (b >= a)'
    lo(i) = min (sto(a(i):b(i)));
    hi(i) = max (sto(a(i):b(i)));
  endfor
  Md = to' >= lo - pad & to' <= hi + pad;
endfunction

## No normal reaches (ti, to) outside |ti - gamma| <= to <= ti + gamma, where
## scene_slice clamps; that leaves a crease along the boundary (the specular
## peak lies on it), which linear interpolation across it would smear over a
## whole table cell.  Continue each row linearly (in to) from the boundary
## instead: the table is then smooth to first order across it.  Extrapolated
## values are kept >= 0.
function T = extend_c1 (T, ti, to, lo, hi, evalrow)
  n = numel (to);
  to = to(:)';
  in = to >= lo & to <= hi;                     # n x n
  ok = sum (in, 2) >= 3;
  j1 = min (n + 1 - sum (cummax (in, 2), 2), n - 1);   # first reachable column
  j2 = max (sum (cummax (fliplr (in), 2), 2), 2);      # last
  r = (1:rows (T))';
  for ch = 1:size (T, 3)
    X = T(:,:,ch);
    a1 = X(sub2ind (size (X), r, j1));
    s1 = (X(sub2ind (size (X), r, j1 + 1)) - a1) ./ (to(j1 + 1) - to(j1))';
    a2 = X(sub2ind (size (X), r, j2));
    s2 = (a2 - X(sub2ind (size (X), r, j2 - 1))) ./ (to(j2) - to(j2 - 1))';
    below = ok & (1:n) < j1;
    above = ok & (1:n) > j2;
    E1 = max (a1 + s1 .* (to - to(j1)'), 0);
    E2 = max (a2 + s2 .* (to - to(j2)'), 0);
    X(below) = E1(below);
    X(above) = E2(above);
    T(:,:,ch) = X;
  endfor
  ## rows whose reachable range holds fewer than 3 grid points (ti near 0, or
  ## light and viewer nearly aligned): 3 points across it, evaluated exactly
  for i = find (! ok)'
    p = linspace (lo(i), hi(i), 3);
    v = reshape (evalrow (ti(i), p), 3, []);    # points x channels
    if (p(3) > p(1))
      sl = (v(2,:) - v(1,:)) / (p(2) - p(1));
      sh = (v(3,:) - v(2,:)) / (p(3) - p(2));
      row = interp1 (p', v, min (max (to', p(1)), p(3)));
    else
      sl = sh = zeros (1, columns (v));
      row = repmat (v(1,:), n, 1);
    endif
    row += (to' < p(1)) .* sl .* (to' - p(1)) + (to' > p(3)) .* sh .* (to' - p(3));
    T(i,:,:) = reshape (max (row, 0), 1, n, []);
  endfor
endfunction

## The inner maps' angle (private to this file): theta_h = angle (N, H), H
## = (L + V)/|L + V|, for an orthographic camera (POV-Ray's slope toward
## H), unless L and V are nearly opposite; to = angle (N, V) otherwise
## (slope toward V; with a perspective camera the aoi pattern).
function C = inner_coord (persp, L, V)
  h = (L + V) / 2;
  C = struct ("half", ! persp && norm (h) > 0.05, "dir", V, "label", "to = angle(N,V)",
              "top", pi/2 - 1e-6, "gamma", acos (max (min (L * V', 1), -1)));
  if (C.half)
    C.dir = h / norm (h);
    C.label = "theta_h = angle(N,H), H = (L+V)/|L+V|";
    C.top = pi;
  endif
endfunction

## the inner angle of the configurations (TI, TO) (same sizes)
function u = inner_of (ti, to, C)
  u = to;
  if (C.half)
    u = half_angle (ti, to, C.gamma);
  endif
endfunction

## the range of the inner angle that some normal reaches at each TI (a
## column), at gamma = angle (L, V) = GAM: to in [|ti - gam|, ti + gam],
## theta_h in [|ti - gam/2|, ti + gam/2] (N on the cone of angle ti about
## L, which is at gam/2 from H; capped where the sums pass pi)
function [lo, hi] = reach_bounds (ti, gam, C)
  g = gam;
  if (C.half)
    g = gam / 2;
  endif
  lo = abs (ti - g);
  hi = min (ti + g, 2 * pi - ti - g);
endfunction

## scene_slice on the grid TI x U of the inner angle (numel (TI) x numel (U)
## x 3): with theta_h, to follows from cos to = 2 cos theta_h cos (gam/2) -
## cos ti (N in the frame of H: N.L + N.V = 2 cos theta_h cos (gam/2))
function R = slice_grid (scene, term, ti, u, gam, C)
  if (! C.half)
    R = scene_slice (scene, term, ti, u);
    return;
  endif
  ti = ti(:);
  u = u(:)';
  to = acos (min (max (2 * cos (u) * cos (gam / 2) - cos (ti), -1), 1));
  to = min (to, pi/2 - 1e-6);   # as the (ti, to) tables: continued across the
                                # silhouette, where scene_slice steps to 0
  TI = repmat (ti, 1, numel (u));
  R = reshape (scene_slice (scene, term, TI(:), to(:), "pairs"), numel (ti), numel (u), []);
endfunction

## the Q-quantile of the largest channel of R (n x m x 3) where M
function v = masked_quantile (R, M, q)
  x = max (R, [], 3)(M & true (rows (R), columns (R)));
  v = 0;
  if (! isempty (x))
    v = quantile (x(:), q);
  endif
endfunction

function v = masked_max (R, M)
  v = 0;
  for ch = 1:size (R, 3)
    x = R(:,:,ch);
    if (any (M(:)))
      v = max (v, max (x(M)));
    endif
  endfor
endfunction

function s = vec (v)
  v(v == 0) = 0;                 # no "-0"
  s = sprintf ("<%.12g, %.12g, %.12g>", v);
endfunction

## one table: slope toward L outside (ti, descending so that the slope value
## 1 - ti/pi ascends), INNER inside (slope toward H or V, or aoi)
function s = table_sdl (id, name, T, ti, to, io, Ki, L, inner)
  parts = cell (1, numel (io) + 2);
  parts{1} = sprintf (["// %s: %d outer entries (angle to the light), inner entries per outer: %d to %d\n" ...
                       "#declare %s = pigment { slope { %s } pigment_map {\n"],
                      name, numel (io), min (sum (Ki, 1)), max (sum (Ki, 1)), id, vec (L));
  for k = numel (io):-1:1
    jo = flipud (find (Ki(:,k)));
    v = [1 - to(jo)'/pi; reshape(T(io(k),jo,:), numel (jo), 3)'];
    parts{numel (io) - k + 2} = [sprintf("[%.9g %s pigment_map {\n", 1 - ti(io(k))/pi, inner), ...
                                 sprintf("[%.9g rgb <%.7g,%.7g,%.7g>]\n", v), "}]\n"];
  endfor
  parts{end} = "} }\n";
  s = [parts{:}];
endfunction

function s = header_sdl (scene, material, opt, tabs, rng_i, rng_o, peak, C)
  nm = name_of (material);
  sname = name_of (scene);
  s = sprintf (["// POV-Ray 3.7 scene written by pov_write_scene (lafortune package)\n" ...
                "// scene '%s', material '%s', %d x %d pixels\n" ...
                "// render: povray +I<this> +O<out>.exr +FE +W%d +H%d -A File_Gamma=1.0\n" ...
                "// tables of f(wi,wo)*E over ti = angle(N,L) in [%.6g, %.6g], %s in [%.6g, %.6g] rad\n" ...
                "// (slope value = 1 - angle/pi); knots %s, entries <= %d, table_tol %g, lobe_tol %g,\n" ...
                "// largest radiance %.6g\n"],
               sname, nm, scene.width, scene.height, scene.width, scene.height,
               rng_i, C.label, rng_o, opt.knots, opt.entries, opt.table_tol, opt.lobe_tol, peak);
  for q = 1:numel (tabs)
    if (tabs(q).kept)
      st = "kept";
    else
      st = "left out";
    endif
    s = [s, sprintf("// %s: largest radiance %.3g of the whole, %s\n", tabs(q).name,
                    tabs(q).contribution, st)];
  endfor
  bg = [0 0 0];
  if (isfield (scene, "background") && numel (scene.background) >= 1)
    bg = double (scene.background(:)') .* [1 1 1];
  endif
  s = [s, sprintf("#version 3.7;\nglobal_settings { assumed_gamma 1.0 ambient_light rgb 0 }\n"), ...
       sprintf("background { rgb %s }\n", vec (bg))];
endfunction

function s = camera_sdl (cam, scene)
  s = sprintf (["// right-handed, y-up world; explicit vectors, so POV-Ray does not mirror\n" ...
                "camera { %s location %s direction %s right %s up %s }\n"],
               cam.type, vec (cam.eye), vec (cam.f), vec (cam.r * cam.w), vec (cam.u * cam.h));
endfunction

function s = light_sdl (scene, L, cam)
  ## far enough that every object is in front of it
  ob = scene.objects;
  ext = norm (cam.eye - double (scene.camera.target(:)')) + cam.w + cam.h;
  for k = 1:numel (ob)
    switch (ob(k).type)
      case "sphere"
        ext = max (ext, norm (ob(k).center) + ob(k).radius);
      case "plane"
        ext = max (ext, norm (ob(k).point));
      case "mesh"
        ext = max (ext, max (sqrt (sum (double (ob(k).vertices) .^ 2, 2))));
    endswitch
  endfor
  ext += norm (cam.eye);
  s = sprintf ("light_source { %s color rgb 1 parallel point_at <0, 0, 0> }\n",
               vec (L * 1000 * ext));
endfunction

## the average of the tables, times their number: their sum
function s = texture_sdl (q)
  fin = sprintf ("finish { ambient 0 emission 0 diffuse %d brilliance 1 specular 0 phong 0 reflection 0 }",
                 max (numel (q), 1));
  if (isempty (q))
    pig = "pigment { rgb 0 }";
  elseif (numel (q) == 1)
    pig = sprintf ("pigment { Lf_term%d }", q);
  else
    pig = ["pigment { average pigment_map {", sprintf(" [1 Lf_term%d]", q), " } }"];
  endif
  s = sprintf ("// POV-Ray applies max(cos ti, 0) and the shadows\n#declare Lf_tex = texture { %s %s }\n",
               pig, fin);
endfunction

function [s, nfd] = objects_sdl (ob, keep, faces)
  parts = {};
  nfd = 0;
  for k = 1:numel (ob)
    if (! keep(k))
      if (strcmp (ob(k).type, "mesh"))
        nfd += rows (ob(k).faces);
      endif
      continue;
    endif
    switch (ob(k).type)
      case "sphere"
        parts{end+1} = sprintf ("sphere { %s, %.12g texture { Lf_tex } }\n",
                                vec (ob(k).center), ob(k).radius);
      case "plane"
        nn = double (ob(k).normal(:)');
        nn /= norm (nn);
        parts{end+1} = sprintf ("plane { %s, %.12g texture { Lf_tex } }\n", vec (nn),
                                nn * double (ob(k).point(:)));
      case "mesh"
        fc = double (ob(k).faces);
        if (! isempty (faces{k}))
          nfd += nnz (! faces{k});
          fc = fc(faces{k},:);
        endif
        [used, ~, j] = unique (fc(:));
        fc = reshape (j, size (fc)) - 1;
        vx = double (ob(k).vertices(used,:));
        p = {sprintf("mesh2 {\n vertex_vectors { %d,\n", rows (vx)), ...
             sprintf("<%.9g,%.9g,%.9g>\n", vx')};
        if (! isempty (ob(k).normals))
          nv = double (ob(k).normals(used,:));
          p(end+1:end+2) = {sprintf(" }\n normal_vectors { %d,\n", rows (nv)), ...
                            sprintf("<%.9g,%.9g,%.9g>\n", nv')};
        endif
        p(end+1:end+3) = {sprintf(" }\n face_indices { %d,\n", rows (fc)), ...
                          sprintf("<%d,%d,%d>\n", fc'), " }\n texture { Lf_tex }\n}\n"};
        parts{end+1} = [p{:}];
    endswitch
  endfor
  s = [parts{:}];
endfunction

%!shared sc, m
%! sc.name = "t"; sc.width = 8; sc.height = 6; sc.spp = 1; sc.seed = 1; sc.background = [0 0 0];
%! sc.camera = struct ("type", "orthographic", "eye", [0 0 5], "target", [0 0 0], "up", [0 1 0],
%!                     "extent", 2.5, "fov", []);
%! sc.light = struct ("type", "directional", "direction", [0 0.6 0.8], "position", [],
%!                    "irradiance", 2);
%! sc.objects = struct ("type", "sphere", "center", [0 0 0], "radius", 1, "point", [],
%!                      "normal", [], "vertices", [], "faces", [], "normals", []);
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);

%!test
%! f = [tempname() ".pov"];
%! unwind_protect
%!   info = pov_write_scene (sc, m, f, "entries", 16);
%!   s = fileread (f);
%!   assert (info.bytes, numel (s));
%!   assert (! isempty (strfind (s, "orthographic location <0, 0, 5> direction <0, 0, -1> right <3.33333333333, 0, 0> up <0, 2.5, 0>")));
%!   assert (! isempty (strfind (s, "slope { <0, 0.6, 0.8> } pigment_map")));      # toward L
%!   assert (! isempty (strfind (s, "slope { <0, 0.316227766017, 0.948683298051> } pigment_map")));  # H
%!   assert (! isempty (strfind (s, "average pigment_map { [1 Lf_term1] [1 Lf_term2] }")));
%!   assert (! isempty (strfind (s, "diffuse 2 ")));
%!   assert ({info.terms.name}, {"diffuse", "lobe 1"});
%!   assert ([info.terms.outer] <= 16 & [info.terms.outer] >= 2);
%!   assert (all ([info.terms.inner] <= 16));
%!   ## the diffuse table is flat in to: 2 inner entries suffice
%!   assert (all (info.terms(1).inner == 2));
%!   ## entries ascend in every map
%!   lines = strsplit (s, "\n");
%!   last = [-1 -1];
%!   for i = 1:numel (lines)
%!     ln = lines{i};
%!     if (strncmp (ln, "#declare Lf_term", 16))
%!       last(1) = -1;
%!     elseif (strncmp (ln, "[", 1))
%!       x = sscanf (ln(2:end), "%f", 1);
%!       lvl = 1 + isempty (strfind (ln, "slope"));
%!       assert (x > last(lvl));
%!       last(lvl) = x;
%!       if (lvl == 1)
%!         last(2) = -1;
%!       endif
%!     endif
%!   endfor
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

%!test
%! ## lit from nearly behind the viewer (|L + V| < 0.1): H is ill-defined,
%! ## the inner maps stay over to (slope toward V)
%! f = [tempname() ".pov"];
%! unwind_protect
%!   sb = sc;
%!   sb.light.direction = [0 0.05 -1] / norm ([0 0.05 -1]);
%!   info = pov_write_scene (sb, m, f);
%!   s = fileread (f);
%!   assert (! isempty (strfind (s, "slope { <0, 0, 1> } pigment_map")));
%!   assert (! isempty (strfind (s, "to = angle(N,V) in")));
%!   assert (info.bytes, numel (s));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

%!test
%! ## a perspective camera with neither cropping nor culling still writes
%! f = [tempname() ".pov"];
%! unwind_protect
%!   sp = scene_make ("sphere", "size", 16, "camera", "perspective");
%!   info = pov_write_scene (sp, m, f, "crop", false, "cull", false);
%!   assert (exist (f, "file") == 2 && info.bytes > 0);
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

%!test
%! ## the tabulated values are scene_slice / cos(ti)
%! f = [tempname() ".pov"];
%! unwind_protect
%!   m1 = m; m1.rho_d = [0 0 0];
%!   info = pov_write_scene (sc, m1, f, "entries", 8, "knots", "uniform", "crop", false);
%!   lines = strsplit (fileread (f), "\n");
%!   x = [];
%!   for i = 1:numel (lines)
%!     if (! isempty (strfind (lines{i}, "slope {")) && lines{i}(1) == "[")
%!       so = sscanf (lines{i}(2:end), "%f", 1);
%!     elseif (strncmp (lines{i}, "[", 1))
%!       x(end+1,:) = [so sscanf(strrep (strrep (lines{i}, "rgb <", " "), ",", " ")(2:end), "%f")'];
%!     endif
%!   endfor
%!   assert (rows (x), 64);
%!   ## inner maps: theta_h = angle (N, H), slope toward H = (L + V)/|L + V|
%!   assert (! isempty (strfind (fileread (f), "slope { <0, 0.316227766017, 0.948683298051> }")));
%!   ti = (1 - x(:,1)) * pi; th = (1 - x(:,2)) * pi;
%!   gam = acos (sc.light.direction * [0 0 1]' / norm (sc.light.direction));
%!   to = acos (min (max (2 * cos (th) * cos (gam / 2) - cos (ti), -1), 1));
%!   for i = 1:rows (x)
%!     R(i,:) = squeeze (scene_slice (sc, m1, ti(i), to(i)))' / cos (ti(i));
%!   endfor
%!   ## where a normal can reach (ti, theta_h); elsewhere the rows are continued
%!   ok = abs (ti - gam / 2) <= th & th <= ti + gam / 2;
%!   assert (nnz (ok) > 20);
%!   assert (x(ok,3:5), R(ok,:), 1e-6 * max (R(:)));
%!   assert (max (R(:)) > 1);
%!   assert (all (x(:,3:5)(:) >= 0));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

%!test
%! ## lobe_tol drops a lobe that never shows; uniform knots fill the maps
%! f = [tempname() ".pov"];
%! unwind_protect
%!   m2 = m; m2.Cxy(2,:) = [0.1 0.1 0.1]; m2.Cz(2,:) = [0.2 0.2 0.2]; m2.e(2,:) = [40 40 40];
%!   info = pov_write_scene (sc, m2, f, "entries", 8, "knots", "uniform");
%!   assert ([info.terms.kept], [true true false]);
%!   assert (info.terms(3).contribution < 1e-20);
%!   assert (info.terms(2).outer, 8);
%!   assert (isempty (strfind (fileread (f), "Lf_term3 =")));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

%!error <Invalid call> pov_write_scene (1, 2)
%!error id=lafortune:badScene pov_write_scene (1, struct ("rho_d", [1 1 1]), "x.pov")
%!error id=lafortune:badMaterial pov_write_scene (sc, 3, "x.pov")
%!error id=lafortune:badOption pov_write_scene (sc, m, "x.pov", "entries", 300)
%!error id=lafortune:badOption pov_write_scene (sc, m, "x.pov", "knots", "cubic")
%!error id=lafortune:badOption pov_write_scene (sc, m, "x.pov", "bogus", 1)
%!error id=lafortune:unwritable pov_write_scene (sc, m, "/nonexistent-dir/x.pov")
%!error id=lafortune:povUnsupported pov_write_scene (setfield (sc, "light", setfield (setfield (sc.light, "type", "point"), "position", [0 0 5])), m, "x.pov")
%!error id=lafortune:badScene pov_write_scene (setfield (sc, "camera", setfield (sc.camera, "type", "fisheye")), m, "x.pov")
