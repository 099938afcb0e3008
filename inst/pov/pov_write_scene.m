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
## angular width.  (Lit from nearly behind the viewer, |L + V| < 0.1, and with a
## perspective camera the inner maps stay over to.)
##
## An analytic @var{material} of any type (@code{brdf_model}) gets one
## table per term: the diffuse term and each lobe, summed by an @code{average} pigment and @code{diffuse} @var{k}
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
## which can be orders of magnitude above the rest, the diffuse part would
## be allowed errors as large as itself), is shared between the tables in proportion to their size (flat
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
## view reaches is below @qcode{"lobe_tol"} times the view's radiance level
## (above) is dropped.  The tables cover only the angles
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
## Lobes whose largest radiance is less than this fraction of the view's
## radiance level are dropped; 0 keeps every lobe.
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
## @item @qcode{"lights"} (256)
## An environment light becomes this many directional lights
## (@code{scene_lights}).  K lights approximate the map; a mirror-like
## material shows them as K points instead of the map's reflection
## (@code{scripts/study_klights.m} measures how close each K comes).
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
## @code{time} (seconds).  For several lights: @code{frames} and
## @code{lights} (K), @code{includes} (the K include files' names),
## @code{kept} (the terms kept per light), @code{entries} and @code{bytes}
## of all files; @code{terms}, @code{gamma}, the ranges and @code{level}
## are empty.
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
## the number of levels.
##
## @strong{Several lights, an environment.}  POV-Ray gives a surface one
## pigment for all its lights, and has no glossy environment lighting (its
## radiosity is diffuse only), while the tables above hold one light's
## radiance.  A scene with a list of directional lights (@code{scene_make}
## option @qcode{"light"}, @qcode{"lights"}, or @code{scene_lights}) is
## therefore written as an animation of K frames, one per light: @var{file}
## holds the camera and the objects (those that any light needs) and
## includes, in frame k, the file @file{BASE_Lkkkk.inc} beside it (BASE the
## name of @var{file} without its extension), which holds light k and its
## tables, made as above for that light alone; the K frames' images add up
## to the image (@code{pov_render} renders and adds them).  The background
## is in frame 1 only.  An environment light (@qcode{"light"},
## @qcode{"environment"}) is first cut into @qcode{"lights"} directional
## lights by @code{scene_lights}.  Each light's tables default to
## @qcode{"entries"} 128 and @qcode{"dense"} 257 (a light carries a K-th of
## the light, and the tables' cost grows with K); give them to change it.
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
  opt = __lafortune_parse_opts__ (varargin, fname,
                    struct ("entries", 256, "knots", "adaptive", "table_tol", 1e-3,
                            "lobe_tol", 1e-4, "crop", true, "cull", true, "pad", 0.02,
                            "dense", 0, "gamma_tol", 0.03, "lights", 256));
  opt = check_opts (opt, fname);
  __lafortune_scene_check__ (scene, fname);
  cam = __lafortune_scene_camera__ (scene);
  kind = __lafortune_material_kind__ (material);
  if (isempty (kind))
    error ("lafortune:badMaterial",
           "%s: MATERIAL must be an analytic model (brdf_model) or a MERL material, got %s",
           fname, class (material));
  endif
  if (! strcmp (kind, "merl"))
    __lafortune_check_bounded__ (__lafortune_check_model__ (material, fname), fname);
  endif
  light = scene.light;
  if (! ischar (file) || isempty (file))
    error ("lafortune:badFile", "%s: FILE must be a non-empty string", fname);
  endif
  if (strcmp (light.type, "environment"))
    scene = scene_lights (scene, opt.lights);
    light = scene.light;
  endif
  if (strcmp (light.type, "lights"))
    ## each light carries a K-th of the light: smaller tables by default
    given = @(nm) any (strcmpi (varargin(1:2:end), nm));
    if (! given ("entries"))
      opt.entries = 128;
    endif
    if (! given ("dense"))
      opt.dense = 257;
    endif
    info = write_lights (scene, material, file, opt, cam, kind, t0);
    return;
  endif
  if (! strcmp (light.type, "directional"))
    error ("lafortune:povUnsupported",
           "%s: the tables need a directional light (then the shading depends on angle (N, L), angle (N, V) and angle (L, V) only), got a %s light; rt_render renders it",
           fname, light.type);
  endif
  L = double (light.direction(:)');
  L /= norm (L);

  T = light_tables (scene, material, opt, cam, kind, L, []);

  ## write
  [osdl, nfd] = pov_sdl ("objects", scene.objects, T.keep, T.faces);
  parts = [{pov_sdl("header", scene, material, opt, T.tabs, T.rng_i, T.rng_o, T.peak, T.C), ...
            pov_sdl("camera", cam, scene), pov_sdl("light", scene, L, cam)}, ...
           T.body, {pov_sdl("texture", find (T.kept)), osdl}];
  __lafortune_write__ (file, fname, "text", parts);
  d = dir (file);
  tabs = T.tabs;
  info = struct ("file", file, "bytes", d.bytes, "terms", tabs,
                 "entries", sum ([tabs.outer]) + sum ([tabs.inner]), "gamma", T.gl,
                 "ti_range", T.rng_i, "to_range", T.rng_o, "peak", T.peak, "level", T.level,
                 "objects", T.keep,
                 "faces_dropped", nfd, "dense", T.ndense, "time", toc (t0));
endfunction


## The tables of one directional light L: what the view reaches (pov_cast,
## or its geometry G when given), the terms tabulated densely by
## scene_slice, the terms left out, and the SDL of each kept term's table.
function T = light_tables (scene, material, opt, cam, kind, L, G)
  fname = "pov_write_scene";
  persp = strcmp (cam.type, "perspective");
  V = -cam.f;
  ## what the view reaches
  top = pi/2 - 1e-6;             # scene_slice is 0 from pi/2 on
  ## the inner maps' angle: theta_h = angle (N, H), H halfway between L and
  ## V, for an orthographic camera (a sharp lobe is a narrow bump in (ti,
  ## theta_h), but a thin sliver along the edge of what normals reach in
  ## (ti, to), where to grows as theta_h squared), else to
  C = pov_tables ("inner_coord", persp, L, V);
  if (opt.crop || opt.cull || persp)     # the gamma levels need the points too
    [S, G] = pov_cast (scene, cam, L, G);
    S.u = pov_tables ("inner_of", S.ti, S.to, C);
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
  if (! strcmp (kind, "merl"))
    [terms, names] = model_terms (material, fname);
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
    samp = pov_tables ("reach_prep", [S.ti, S.u]);   # once for every grid
  else
    samp = [];
  endif
  ## the angle gamma between L and V: one value (orthographic), or levels
  ## over the range the visible points reach (perspective)
  if (persp)
    gl = pov_tables ("gamma_levels", scene, material, L, S, rng_i, rng_o, opt);
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
    reach = pov_tables ("reach_mask", samp, t', u', opt.pad);
  endif
  for g = 1:ng
    sg = pov_tables ("view_at_gamma", scene, L, gl(g));
    for q = 1:nt
      D{g,q} = pov_tables ("term_grid", sg, terms{q}, rng_i, rng_o, n, samp, opt, gl(g), C);
      contrib(q) = max (contrib(q), D{g,q}.max);
    endfor
    [lo, hi] = pov_tables ("reach_bounds", t', gl(g), C);
    Mc = u >= lo & u <= hi & reach;
    Rc = pov_tables ("slice_grid", sg, material, t, u, gl(g), C);
    peak = max ([peak, contrib, pov_tables("masked_max", Rc, Mc)]);
    level = max (level, pov_tables ("masked_quantile", Rc, Mc, 0.99));
  endfor
  ## the error allowed is relative to the view's radiance level: its 99th
  ## percentile over the reached angles (a measured material's specular
  ## peak can be orders of magnitude above the rest; relative to it, the
  ## diffuse part of the picture would get errors as large as itself)
  level = min (peak, level);
  if (! (level > 0))
    level = peak;
  endif
  if (peak > 0)
    contrib /= peak;
  endif
  ## a lobe that never shows is dropped: its largest radiance where the view
  ## reaches is below lobe_tol times the view's radiance level (not the
  ## peak: a sharp lobe's peak, between the pixels, can be orders of
  ## magnitude above the broad lobe that carries the body); lobe_tol applies to lobes, the
  ## diffuse term stays
  kept = contrib > 0 & contrib * peak >= opt.lobe_tol * level;
  d = strcmp (names, "diffuse");
  kept(d) = contrib(d) > 0;

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
      body{end+1} = pov_sdl ("gamma", id, names{q}, gl, cam.eye, L);
    else
      body{end+1} = sprintf ("#declare %s = pigment { %s_1 }\n", id, id);
    endif
  endfor

  T = struct ("body", {body}, "tabs", tabs, "kept", kept, "keep", keep, "faces", {faces},
              "rng_i", rng_i, "rng_o", rng_o, "peak", peak, "level", level, "gl", gl,
              "ndense", ndense, "C", C, "G", G);
endfunction

## The knots and the SDL of one term's table at one gamma level: outer map
## over ti, inner maps over the inner angle (C); NO and NI count the entries.
function [sdl, no, ni] = term_sdl (Dq, tol, peak, opt, L, C, name, id, persp)
  [T, io, Ki] = pov_tables ("term_knots", Dq, tol, peak, opt);
  no = numel (io);
  ni = sum (Ki, 1);
  if (persp)
    inner = "aoi";                   # 1 - angle (N, ray toward the eye)/pi
  else
    inner = sprintf ("slope { %s }", pov_sdl ("vec", C.dir));
  endif
  sdl = pov_sdl ("table", id, name, T, Dq.ti, Dq.to, io, Ki, L, inner);
endfunction

## K directional lights: one POV-Ray frame per light.  POV-Ray's surfaces
## take one pigment for every light, but each light needs its own table
## (the radiance depends on the angles to that light), so FILE renders
## light k in frame k (+KFI1 +KFF<K>): it includes the file BASE_Lkkkk.inc
## beside it, which holds the light and its tables; the frames' images sum
## to the image (pov_render does it).  The geometry is written once, in
## FILE, with the objects any light needs.
function info = write_lights (scene, material, file, opt, cam, kind, t0)
  fname = "pov_write_scene";
  lt = scene.light;
  K = rows (lt.directions);
  [dd, base] = fileparts (file);
  nob = numel (scene.objects);
  keep = false (1, nob);
  faces = cell (1, nob);
  incs = cell (1, K);
  G = [];
  bytes = 0;
  entries = 0;
  peak = 0;
  kept = zeros (1, K);
  for k = 1:K
    L = double (lt.directions(k,:));
    L /= norm (L);
    sk = scene;
    sk.light = struct ("type", "directional", "direction", L, "position", [],
                       "irradiance", double (lt.irradiance(k,:)));
    incs{k} = sprintf ("%s_L%04d.inc", base, k);
    head = sprintf ("// light %d of %d: direction %s, irradiance %s\n", k, K,
                    pov_sdl ("vec", L), pov_sdl ("vec", sk.light.irradiance));
    if (any (sk.light.irradiance > 0))
      T = light_tables (sk, material, opt, cam, kind, L, G);
      G = T.G;
      keep |= T.keep;
      for q = 1:nob
        if (! isempty (T.faces{q}))
          if (isempty (faces{q}))
            faces{q} = T.faces{q};
          else
            faces{q} |= T.faces{q};
          endif
        endif
      endfor
      parts = [{head, pov_sdl("light", sk, L, cam)}, T.body, {pov_sdl("texture", find (T.kept))}];
      entries += sum ([T.tabs.outer]) + sum ([T.tabs.inner]);
      peak = max (peak, T.peak);
      kept(k) = nnz (T.kept);
    else
      parts = {head, pov_sdl("texture", [])};
    endif
    f = fullfile (dd, incs{k});
    __lafortune_write__ (f, fname, "text", parts);
    d = dir (f);
    bytes += d.bytes;
  endfor
  for q = 1:nob                        # an object no light needs: left out
    if (! isempty (faces{q}))
      keep(q) = any (faces{q});
    endif
  endfor
  if (! opt.cull)
    keep = true (1, nob);
    faces = cell (1, nob);
  endif
  [osdl, nfd] = pov_sdl ("objects", scene.objects, keep, faces);
  parts = {pov_sdl("frames", scene, material, K, base), pov_sdl("camera", cam, scene), osdl};
  __lafortune_write__ (file, fname, "text", parts);
  d = dir (file);
  info = struct ("file", file, "bytes", bytes + d.bytes, "terms", [], "entries", entries,
                 "gamma", [], "ti_range", [], "to_range", [], "peak", peak, "level", [],
                 "objects", keep, "faces_dropped", nfd, "dense", opt.dense, "time", toc (t0),
                 "frames", K, "includes", {incs}, "lights", K, "kept", kept);
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
  K = opt.lights;
  if (! (isnumeric (K) && isscalar (K) && isreal (K) && K >= 1 && K == fix (K)))
    error ("lafortune:badOption", "%s: \"lights\" must be a positive integer", fname);
  endif
  d = opt.dense;
  if (! isscalar (d) || ! isnumeric (d) || d != fix (d) || (d != 0 && d < opt.entries))
    error ("lafortune:badOption", "%s: \"dense\" must be 0 (automatic) or an integer >= \"entries\"",
           fname);
  endif
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
%!test
%! ## a model infinite at grazing angles: refused, and no file written
%! f = [tempname() ".pov"];
%! boom = struct ("rho_d", [0 0 0], "Cxy", [-1.5 0 0], "Cz", [0.9 0 0], "e", [738 1 1]);
%! try
%!   pov_write_scene (sc, boom, f);
%!   error ("test:none", "no error");
%! catch err
%!   assert (err.identifier, "lafortune:unboundedModel");
%! end_try_catch
%! assert (! exist (f, "file"));
%!error id=lafortune:badOption pov_write_scene (sc, m, "x.pov", "entries", 300)
%!error id=lafortune:badOption pov_write_scene (sc, m, "x.pov", "knots", "cubic")
%!error id=lafortune:badOption pov_write_scene (sc, m, "x.pov", "bogus", 1)
%!error id=lafortune:unwritable pov_write_scene (sc, m, "/nonexistent-dir/x.pov")
%!error id=lafortune:povUnsupported pov_write_scene (setfield (sc, "light", setfield (setfield (sc.light, "type", "point"), "position", [0 0 5])), m, "x.pov")
%!error id=lafortune:badScene pov_write_scene (setfield (sc, "camera", setfield (sc.camera, "type", "fisheye")), m, "x.pov")
