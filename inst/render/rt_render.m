## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{img} =} rt_render (@var{scene}, @var{material})
## @deftypefnx {lafortune} {@var{img} =} rt_render (@var{scene}, @var{material}, @var{option}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{img}, @var{info}] =} rt_render (@dots{})
## @deftypefnx {lafortune} {[@var{img}, @var{info}, @var{cache}] =} rt_render (@dots{})
## @deftypefnx {lafortune} {@var{img} =} rt_render (@var{scene}, @var{material}, "cache", @var{cache}, @dots{})
## Render a scene with a measured (MERL) or Lafortune material: the Octave raytracer.
##
## @var{scene} is a struct from @code{scene_make}; every object gets
## @var{material} (a MERL struct from @code{merl_read}/@code{merl_synth} or an
## analytic model of any type, @code{brdf_model}, else error
## @code{lafortune:badMaterial}), shaded through @code{material_eval}.  @var{img} is
## the @code{scene.height} x @code{scene.width} x 3 linear HDR image:
## the mean over @code{scene.spp} primary rays per pixel of the
## radiance f(wi, wo) max(cos theta_i, 0) E, 0 where a shadow ray toward the
## light hits an object, @code{scene.background} where the ray hits nothing.
##
## Shading frame: the geometric normal for spheres and planes, the
## interpolated vertex normal for meshes that have normals (else the
## triangle's normal); a normal facing away from the viewer is flipped (both
## sides of a surface are lit alike), and a mesh shading normal that still
## faces away from the viewer is replaced by the geometric one.  The light
## must also be above the geometric surface.  Isotropic materials do not
## depend on the azimuth of the local frame, so x and y are any orthonormal
## completion of the normal.
##
## Modes (option @code{"mode"}):
##
## @table @code
## @item "slice"
## with an orthographic camera and a directional light the angle gamma
## between the light L and the view V is the same at every surface point, so
## the radiance f(wi, wo) cos(theta_i) E of an isotropic material depends on
## the normal N only through two angles.  The renderer tabulates that 2-D
## slice once, with @code{scene_slice} (the evaluation the POV-Ray exporter
## shares), and interpolates it bilinearly per hit instead of evaluating the
## material per sample.  The table is indexed by the half-vector angles of N:
## theta_h = angle (N, H), H = (L + V)/|L + V|, on a grid uniform in
## sqrt (theta_h/(pi/2)) (the MERL spacing, dense at the specular peak
## theta_h = 0), and the azimuth psi of N about H, measured from the plane of
## L and V, uniform in [0, pi] (psi and -psi give the same radiance).  Each
## grid node is mapped to its angles ti = angle (N, L), to = angle (N, V) and
## looked up in @code{scene_slice}; the table holds that radiance divided by
## cos (ti), and the lookup multiplies the exact cos (ti) of the hit back, so
## the kink of max (cos ti, 0) at the terminator is not interpolated (ti and
## to are capped just below 90 degrees, so the table continues smoothly
## across the terminator and the silhouette).  Unlike a table over
## (ti, to), whose specular ridge runs along the diagonal and the edge of the
## reachable set, these coordinates keep a sharp lobe on a few rows:
## default size @code{"slice_size"} = [128 64] (theta_h x psi), single
## precision, 128 x 64 x 3 x 4 bytes = 98 kB, 356 times less than the 35 MB
## of a MERL table.  For analytic models the image then differs from the
## direct one by less than 1e-4 of its peak (RMS; test_render asserts it);
## for MERL materials the difference does not fall with the table size,
## because the direct nearest-bin lookup itself jumps at the MERL bin
## edges, which any interpolated table smooths.
## @item "direct"
## evaluate @code{material_eval} per hit, in the local frame.
## @item "auto"
## (default) "slice" when possible, else "direct" (perspective camera or point
## light); "lights" under an environment light or a list of lights.
## @end table
##
## Lights mode is not a value of @code{"mode"}: it is the only mode (for any
## camera) for @code{scene.light.type} @qcode{"environment"} or
## @qcode{"lights"} (@code{scene_make}), which @qcode{"auto"} and
## @qcode{"direct"} both give (@code{info.mode} is @qcode{"lights"}).  Each
## pixel sample that hits a surface takes @qcode{"light_samples"} directions (default
## @code{scene.light.samples}) drawn from the map in proportion to its
## luminance times sin theta (a piecewise-constant 2-D distribution over the
## texels, marginal over the rows and conditional within each, as pbrt's
## image infinite light), stratified (the first points of the R2 sequence,
## shifted by a hash of the sample and @code{scene.seed}); or, for a list of
## lights, every light.  Each gets a shadow ray into the scene's own
## geometry and adds f (wi, wo) cos (theta_i) times the map's radiance over
## the density, divided by the count (or times the light's irradiance).
## Under an environment light option @code{"sampling"} chooses how the
## @qcode{"light_samples"} directions are drawn: @qcode{"mis"} (the
## default, @qcode{"auto"}): a share of them from the BRDF density
## (@code{brdf_sample}) and the rest from the map as above, combined by
## multiple importance sampling with the balance heuristic, each sample
## weighted by the map's radiance over n_light p_light + n_brdf p_brdf.
## The share is option @qcode{"brdf_share"}: a number in [0, 1] (0.5 was
## 0.11.0's), or @qcode{"auto"} (the default), 0.5 (1 - 1/m2) with m2 the
## density's second moment against the cosine-weighted hemisphere
## (@code{__lafortune_density_m2__}; 0 below 0.1, where a few BRDF samples
## cost more than they give): none for a diffuse material, whose light the
## map's own samples find better, about half for a sharp one;
## @qcode{"brdf"}: all from the BRDF density; @qcode{"light"}: all from
## the map (0.10.3's sampler, bit for bit).  The density is option
## @code{"density"} (a model or a @code{brdf_density}), by default
## @code{brdf_density (material)}: an analytic model's own lobes; for a
## MERL material its field @code{sampler}, else a table of its data.
## The weights depend on the density only, so every material shaded from
## the cache uses the measured data's density and stays unbiased.
##
## Samples: the @code{scene.spp} primary rays of a pixel are stratified,
## one in each cell of an nx x ny grid over the pixel (nx ny = spp, as
## square as spp allows), at a random place in its cell or, with
## @code{scene.jitter} false (@code{scene_make} option @qcode{"jitter"}), at
## the cell centre: one ray through the pixel centre for spp = 1, and for
## spp = n^2 the regular n x n grid of POV-Ray's anti-aliasing
## (@code{pov_render} option @qcode{"antialias"}, n, which averages it with
## the centre ray), so that the two renderers can be compared without
## sampling noise.  Stratified samples
## converge much faster than independent ones where a pixel covers many
## small facets (a 100k-triangle mesh at 256 x 512).
##
## Other options: @code{"light_samples"} (lights mode, see above),
## @code{"jitter"} (default @code{scene.jitter}, else true:
## overrides it), @code{"progress"} (default true: on renders longer than
## 2 s a line "rt_render: 42% done, 12 s left" is updated in place on a
## terminal; when stdout is not a terminal, a line is printed every 10% or
## 30 s, with no carriage returns),
## @code{"chunk"} (rays traced at once, default 65536: bounds the memory).
## The jitter comes from @code{rand} seeded with @code{scene.seed} (the
## generator's state is restored afterwards), so the same scene gives the same
## image.
##
## Trace once, shade many (slice and lights modes): in lights mode the
## cache keeps, for every light sample that reaches a surface, the three
## numbers an isotropic material depends on, [cos theta_i, cos theta_o,
## wi . wo], and its weight (about 40 bytes each), so that another material
## from the cache is only evaluated there, on the same light samples: the
## measured data and its fits then share their noise.  In slice mode the
## trace does not depend on the
## material, so the third output @var{cache} keeps what the shading needs of
## every primary sample (the lit hits' table weights and cos (theta_i), the
## misses; about 25 bytes per lit sample and 1 per sample), and
## @code{rt_render (scene, other, "cache", cache)} renders another material
## in the same scene with the same options (@code{"jitter"}, @code{"chunk"},
## @code{"slice_size"}) without tracing a ray.  The image is bit for bit the
## one a full render gives.  A render with @var{cache} returns it again (so a
## loop can pass its own output back), and @var{cache} is empty in direct mode; a cache
## from another scene or other options is an error
## (@code{lafortune:badOption}).
##
## @var{info} reports: @code{mode}, @code{time_setup} (BVH, slice table),
## @code{time_intersect} (camera rays and their intersection),
## @code{time_shadow}, @code{time_shade}, @code{time_total} (seconds),
## @code{rays} (primary + shadow), @code{rays_per_second}
## (@code{rays / time_total}), @code{material_bytes} (memory of what the
## shading used: the slice table, or the whole material struct in direct
## mode), @code{slice_size}, @code{spp}, @code{cached} (true when the
## render used @var{cache}; @code{rays} then counts the rays the cached
## trace took), @code{light_samples} (lights mode: per pixel sample, or the
## number of lights), @code{evaluations} (lights mode: the material's
## evaluations), @code{time_brdf} (their time), @code{sampling} (the
## sampling used), @code{density} (the model the BRDF samples follow,
## empty for light sampling) and @code{brdf_share} (the share of the
## light samples drawn from it).
##
## @example
## @group
## scene = scene_make ("sphere", "size", [128 128], "spp", 4);
## brdf = merl_standin ("green-metallic-paint");  # or merl_read ("FILE.binary")
## [img, info] = rt_render (scene, brdf);
## info.material_bytes        # the slice, not the 35 MB table
## [img2, info2] = rt_render (scene, brdf, "mode", "direct");
## img_psnr (img2, img)       # the slice against per-sample shading
## ## one trace, many materials
## [img, ~, cache] = rt_render (scene, brdf);
## fit = lafortune_fit (merl_samples (brdf), 2);
## img3 = rt_render (scene, fit, "cache", cache);   # no ray traced
## ## under an environment map, the same light samples for both
## env = scene_make ("sphere", "size", [128 128], "light", "environment", "map", "sky");
## [ref, ~, c] = rt_render (env, brdf, "light_samples", 64);
## img4 = rt_render (env, fit, "cache", c, "light_samples", 64);
## @end group
## @end example
## @seealso{scene_make, scene_slice, material_eval, rt_intersect, rt_bvh, img_psnr}
## @end deftypefn

function [img, info, cache] = rt_render (scene, material, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  t_start = tic ();
  __lafortune_scene_check__ (scene, "rt_render");
  kind = __lafortune_material_kind__ (material);
  if (isempty (kind))
    error ("lafortune:badMaterial",
           "rt_render: MATERIAL must be a MERL material (fields data, valid) or an analytic model (a Lafortune model, fields rho_d, Cxy, Cz, e, or see brdf_model), got %s",
           class (material));
  endif
  if (! strcmp (kind, "merl"))
    __lafortune_check_bounded__ (__lafortune_check_model__ (material, "rt_render"), "rt_render");
  endif
  opt = __lafortune_parse_opts__ (varargin, "rt_render",
                    struct ("mode", "auto", "progress", true, "jitter", scene_jitter (scene),
                            "chunk", 65536, "slice_size", [128 64], "cache", [],
                            "light_samples", [], "sampling", "auto", "density", [],
                            "brdf_share", "auto"));
  if (! ischar (opt.mode) || ! any (strcmp (opt.mode, {"auto", "slice", "direct"})))
    error ("lafortune:badOption", "rt_render: MODE must be \"auto\", \"slice\" or \"direct\"");
  endif
  if (! (isscalar (opt.jitter) && (islogical (opt.jitter) || isnumeric (opt.jitter))))
    error ("lafortune:badOption", "rt_render: JITTER must be true or false");
  endif
  if (! (isscalar (opt.chunk) && opt.chunk >= 1))
    error ("lafortune:badOption", "rt_render: CHUNK must be a positive integer");
  endif
  n = opt.slice_size;
  if (! (isnumeric (n) && numel (n) == 2 && all (n >= 4) && all (n == fix (n))))
    error ("lafortune:badOption",
           "rt_render: SLICE_SIZE must be [NH NPSI], integers >= 4");
  endif
  n = double (n(:).');
  canslice = strcmp (scene.camera.type, "orthographic") ...
             && strcmp (scene.light.type, "directional");
  many = any (strcmp (scene.light.type, {"environment", "lights"}));
  ns = [];
  if (strcmp (scene.light.type, "environment"))
    ns = scene.light.samples;
    if (! isempty (opt.light_samples))
      ns = opt.light_samples;
      if (! (isnumeric (ns) && isscalar (ns) && isreal (ns) && ns >= 1 && ns == fix (ns)))
        error ("lafortune:badOption", "rt_render: LIGHT_SAMPLES must be a positive integer");
      endif
    endif
    ns = double (ns);
  elseif (strcmp (scene.light.type, "lights"))
    ns = rows (scene.light.directions);
  endif
  sampling = env_sampling (opt.sampling, scene, opt.brdf_share);
  mode = opt.mode;
  if (many)
    if (strcmp (mode, "slice"))
      error ("lafortune:badOption",
             "rt_render: mode \"slice\" needs a directional light, got %s light", scene.light.type);
    endif
    mode = "lights";
  elseif (strcmp (mode, "auto"))
    if (canslice)
      mode = "slice";
    else
      mode = "direct";
    endif
  elseif (strcmp (mode, "slice") && ! canslice)
    error ("lafortune:badOption",
           "rt_render: mode \"slice\" needs an orthographic camera and a directional light, got %s and %s",
           scene.camera.type, scene.light.type);
  endif

  ## ---- setup: acceleration structures, normals, the slice table
  if (isempty (opt.cache))             # a cached render traces nothing
    [objs, epsilon] = scene_setup (scene);
  endif
  cam = __lafortune_scene_camera__ (scene);
  env = [];
  if (strcmp (mode, "slice"))
    [Rm, sl] = slice_table (scene, material, n, -cam.f);
    material_bytes = numel (Rm) * 4;
  else
    if (many)
      env = struct ("D", [], "ns", ns);
      if (strcmp (scene.light.type, "environment"))
        env.D = env_dist (scene.light);
      endif
      if (! strcmp (sampling, "light") && isempty (opt.cache))
        env = mis_env (env, sampling, ns, material, opt.density, opt.brdf_share);
      endif
    endif
    Rm = [];
    w = whos ("material");
    material_bytes = w.bytes;
  endif
  time_setup = toc (t_start);

  ## ---- trace in chunks of samples; sample k = pixel + (s-1)*npix
  H = scene.height;
  W = scene.width;
  npix = H * W;
  spp = scene.spp;
  total = npix * spp;
  chunk = min (round (opt.chunk), total);
  if (many)                            # camera samples at once: ns light samples each
    chunk = max (1, min (floor (round (opt.chunk) / ns), total));
  endif
  acc = zeros (npix, 3);
  bg = double (scene.background(:).');
  nshadow = 0;
  t_int = t_sh = t_shade = t_brdf = 0;
  ## the trace cache: what slice shading needs of each chunk's trace
  key = struct ("scene", scene, "jitter", logical (opt.jitter), "chunk", chunk, "slice_size", n,
                "light_samples", ns, "sampling", sampling, "brdf_share", opt.brdf_share);
  cached = ! isempty (opt.cache);
  if (cached)
    if (strcmp (mode, "direct"))
      error ("lafortune:badOption",
             "rt_render: CACHE serves slice mode (orthographic camera, directional light) and lights mode (environment or lights) only, this render is in %s mode",
             mode);
    endif
    if (! (isstruct (opt.cache) && isscalar (opt.cache) && isfield (opt.cache, "key")
           && isfield (opt.cache, "chunks") && isequal (opt.cache.key, key)))
      error ("lafortune:badOption",
             "rt_render: CACHE must be the third output of rt_render for the same scene and options (jitter, chunk, slice_size, light_samples, sampling, brdf_share)");
    endif
    nshadow = opt.cache.nshadow;
  endif
  keep = nargout > 2 && ! strcmp (mode, "direct") && ! cached;
  nevals = 0;
  if (keep && strcmp (mode, "slice"))
    chunks = cell (1, ceil (total / chunk));
  endif
  if (opt.progress)
    prog = progress_line ("rt_render");
  endif
  ## lights mode shades after the trace, many chunks' light samples in one
  ## evaluation of the material (the compiled core shares big calls out over
  ## the cores), the sums chunk by chunk; from a cache it only shades
  lights = strcmp (mode, "lights");
  if (lights)
    batch = 2 ^ 18;                    # light samples shaded at once
    if (cached)
      chunks = opt.cache.chunks;
      Xall = opt.cache.X;
      nrow = opt.cache.rows;
    else
      chunks = cell (1, ceil (total / chunk));
      nrow = zeros (1, numel (chunks));
      Xs = cell (1, numel (chunks));
    endif
    done = 0;                          # the chunks shaded so far
  endif
  last = total - 1;
  if (lights && cached)                # nothing to trace
    last = -1;
  endif
  if (cached && strcmp (mode, "slice"))
    ## the loop below over the cache's chunks, compiled, in one call (the
    ## same operations: slice_rad, then chunk_sums, chunk by chunk)
    t0 = tic ();
    [done, A] = __lafortune_oct_call__ ("__rt_slice_sum__", "rt_render", Rm, opt.cache.chunks,
                                        chunk, total, npix, bg);
    if (done)
      acc = A;
      last = -1;
      t_shade += toc (t0);
      if (opt.progress)
        prog = progress_line (prog, 1, toc (t_start));
      endif
    endif
  endif
  state = rand ("state");
  unwind_protect
    rand ("state", scene.seed);
    for k0 = 0:chunk:last
      m = min (chunk, total - k0);
      ic = k0 / chunk + 1;
      if (cached)
        Tc = opt.cache.chunks{ic};
      else
        k = k0 + (0:m-1).';
        t0 = tic ();
        [O, D] = sample_rays (scene, cam, k, opt.jitter);
        t_int += toc (t0);
        [T, tt] = scene_trace (objs, scene, O, D, epsilon, k, env);
        t_int += tt(1);
        t_sh += tt(2);
        t_shade += tt(3);
        nshadow += T.nshadow;
      endif

      if (lights)                      # kept, and shaded a batch at a time
        chunks{ic} = struct ("h", int32 (T.h(T.S.own)), "w", single (T.S.w), "miss", T.miss);
        Xs{ic} = T.S.X;
        nrow(ic) = rows (T.S.X);
        if (sum (nrow(done+1:ic)) >= batch || k0 + m >= total)
          t0 = tic ();
          [acc, te] = shade_lights (acc, material, vertcat (Xs{done+1:ic}), chunks, nrow,
                                    done+1:ic, chunk, bg);
          t_brdf += te;
          t_shade += toc (t0);
          if (! keep)
            [Xs{done+1:ic}] = deal ([]);
          endif
          done = ic;
        endif
        if (opt.progress)
          prog = progress_line (prog, (k0 + m) / total, toc (t_start));
        endif
        continue;
      endif

      t0 = tic ();
      if (! cached)
        il = find (T.lit)(:);        # a column, also for a chunk of one sample
        if (strcmp (mode, "slice"))
          Tc = struct ("h", int32 (T.h(il)), "w", slice_weights (sl, T.Ns(il,:)),
                       "cosi", T.cosi(il), "miss", T.miss);
          if (keep)
            chunks{ic} = Tc;
          endif
        endif
      endif
      if (strcmp (mode, "slice"))
        rad = slice_rad (Rm, Tc.w, Tc.cosi);
        lith = Tc.h;
        miss = Tc.miss;
      else
        rad = zeros (numel (il), 3);
        if (! isempty (il))
          [wi, wo] = local_dirs (T.Ns(il,:), T.L(il,:), T.V(il,:));
          rad = material_eval (material, wi, wo) .* T.cosi(il) .* T.E(il,:);
        endif
        lith = T.h(il);
        miss = T.miss;
      endif
      [p, sums] = chunk_sums (npix, k0, lith, rad, miss, bg);
      acc(p,:) += sums;                # (acc is this function's own: no copy)
      t_shade += toc (t0);

      if (opt.progress)
        prog = progress_line (prog, (k0 + m) / total, toc (t_start));
      endif
    endfor
  unwind_protect_cleanup
    rand ("state", state);
  end_unwind_protect
  if (lights && cached)                # the cache's chunks, a batch at a time
    off = [0, cumsum(nrow)];
    while (done < numel (chunks))
      upto = max (done + 1, find (off(2:end) - off(done+1) <= batch, 1, "last"));
      t0 = tic ();
      [acc, te] = shade_lights (acc, material, Xall(off(done+1)+1:off(upto+1),:), chunks,
                                nrow, done+1:upto, chunk, bg);
      t_brdf += te;
      t_shade += toc (t0);
      done = upto;
    endwhile
  endif
  if (lights)
    nevals = sum (nrow);
  endif
  img = reshape (acc / spp, H, W, 3);
  cache = [];
  if (keep)
    cache = struct ("key", key, "chunks", {chunks}, "nshadow", nshadow);
    [cache.density, cache.brdf_share] = sampling_used (env, ns, []);   # what the weights are made with
    if (lights)                        # every light sample's X in one array
      cache.rows = nrow;
      cache.X = vertcat (Xs{:});
    endif
  elseif (cached)
    cache = opt.cache;
  endif
  time_total = toc (t_start);
  if (opt.progress)
    progress_line (prog, "done", time_total);
  endif
  rays = total + nshadow;
  info = struct ("mode", mode, "time_setup", time_setup, "time_intersect", t_int,
                 "time_shadow", t_sh, "time_shade", t_shade, "time_total", time_total,
                 "rays", rays, "rays_per_second", rays / time_total,
                 "material_bytes", material_bytes, "slice_size", [], "spp", spp,
                 "cached", cached, "light_samples", ns, "evaluations", nevals,
                 "time_brdf", t_brdf, "sampling", sampling, "density", [], "brdf_share", []);
  [info.density, info.brdf_share] = sampling_used (env, ns, opt.cache);
  if (strcmp (mode, "slice"))
    info.slice_size = n;
  endif
endfunction

## the density the BRDF samples followed and their share of the NS light
## samples: this render's (ENV.S), else those of the trace cache CACHE, else
## none (light sampling)
function [density, share] = sampling_used (env, ns, cache)
  density = share = [];
  if (isfield (env, "S"))
    density = env.S.model;
    share = env.nb / ns;
  elseif (isstruct (cache) && isfield (cache, "density"))
    density = cache.density;
    if (isfield (cache, "brdf_share"))
      share = cache.brdf_share;
    endif
  endif
endfunction

## the sampling of an environment light: OPT ("auto", "light", "brdf" or
## "mis"); "auto" is "mis" under an environment light, "light" under a list
## of lights or a single light (nothing to combine); and SHARE, the option
## brdf_share, checked: "auto" or a number in [0, 1]
function sampling = env_sampling (opt, scene, share)
  if (! ischar (opt) || ! any (strcmp (opt, {"auto", "light", "brdf", "mis"})))
    error ("lafortune:badOption",
           "rt_render: SAMPLING must be \"auto\", \"light\", \"brdf\" or \"mis\", got %s",
           __lafortune_arg_str__ (opt));
  endif
  env = strcmp (scene.light.type, "environment");
  if (strcmp (opt, "auto"))
    opt = merge (env, "mis", "light");
  elseif (! env && ! strcmp (opt, "light"))
    error ("lafortune:badOption",
           "rt_render: SAMPLING \"%s\" needs an environment light, got a %s light", opt,
           scene.light.type);
  endif
  if (! ((ischar (share) && strcmp (share, "auto"))
         || (isnumeric (share) && isreal (share) && isscalar (share) && share >= 0 && share <= 1)))
    error ("lafortune:badOption",
           "rt_render: BRDF_SHARE must be \"auto\" or a number in [0, 1], got %s",
           __lafortune_arg_str__ (share));
  endif
  sampling = opt;
endfunction

## the BRDF samples of an environment light: NS split into light and BRDF
## samples (mis: half each, the light's the larger half; brdf: all), and
## the density (DENSITY, else the material's: brdf_density)
function env = mis_env (env, sampling, ns, material, density, share)
  if (isempty (density))
    density = material;
  endif
  env.S = brdf_density (density);
  if (strcmp (sampling, "brdf"))
    env.nb = ns;
  else
    if (strcmp (share, "auto"))        # about none for a diffuse density, about half for a sharp one
      share = 0.5 * (1 - 1 / max (__lafortune_density_m2__ (env.S), 1));
      share *= share >= 0.1;           # a few BRDF samples cost more than they give
    endif
    env.nb = floor (ns * share + 0.5 - 1e-9);   # a half rounds down: the light's the larger half
  endif
  env.nl = ns - env.nb;
  env.mis = env.nb > 0;                # no BRDF samples: light sampling's estimator, and its cost
endfunction

## Lights mode: the chunks IC (whose light samples' X, stacked, are X) shaded
## by MATERIAL in one evaluation and added to ACC chunk by chunk; TE is the
## evaluation's time
function [acc, te] = shade_lights (acc, material, X, chunks, nrow, ic, chunk, bg)
  t1 = tic ();
  F = material_x (material, X);
  te = toc (t1);
  r0 = 0;
  for i = ic
    Tc = chunks{i};
    rad = F(r0+1:r0+nrow(i),:) .* double (Tc.w);
    r0 += nrow(i);
    [p, sums] = chunk_sums (rows (acc), (i - 1) * chunk, Tc.h, rad, Tc.miss, bg);
    acc(p,:) += sums;
  endfor
endfunction

## each pixel's sum over a chunk's samples K0+1 ... K0+M (M = numel
## (MISS); sample k at pixel mod (k - 1, NPIX) + 1), in their order: the lit
## samples LITH (int32 indices in the chunk) with radiance RAD, the misses
## MISS with the background BG; the samples that add 0 (shadow, and misses
## on a black background) are left out, which changes no bit of the sum.
## The pixels P and their sums S, which the caller adds to its image
## (acc(P,:) += S: in the caller, whose image it is, Octave changes it in
## place; a function that took and returned the image would copy it).  The
## oct-file __rt_accum__ makes the same sums, compiled, when it is built
## (P the pixels reached); this code is the definition and the reference
## (P every pixel: adding 0 to the others changes no bit, as the image holds
## no -0)
function [p, s] = chunk_sums (npix, k0, lith, rad, miss, bg)
  [done, p, s] = __lafortune_oct_call__ ("__rt_accum__", "rt_render", npix, k0,
                                         int32 (lith), rad, logical (miss), bg);
  if (done)
    return;
  endif
  pix = mod (k0 + (0:numel (miss)-1).', npix) + 1;
  j = double (lith);
  if (any (bg))
    j = [j; find(miss)];
    rad = [rad; repmat(bg, nnz (miss), 1)];
    [j, o] = sort (j);
    rad = rad(o,:);
  endif
  p = (1:npix).';
  s = zeros (npix, 3);
  for c = 1:3
    s(:,c) = accumarray (pix(j), rad(:,c), [npix 1]);
  endfor
endfunction

## The slice table: radiance at the normals N(theta_h, psi) about the half
## vector, through scene_slice.  RM is NH*NPSI x 3 single, column-major
## (theta_h fastest).
function [Rm, sl] = slice_table (scene, material, n, V)
  L = scene.light.direction(:).' / norm (scene.light.direction);
  V = V(:).' / norm (V);
  H = L + V;
  if (norm (H) < 1e-9)                     # light straight behind: nothing lit is seen
    H = null (L)(:,1).';
  endif
  H /= norm (H);
  T = L - V;
  T -= (T * H.') * H;
  if (norm (T) < 1e-9)                     # light at the camera: psi does not matter
    T = null (H)(:,1).';
  endif
  T /= norm (T);
  B = cross (H, T);
  nh = n(1);
  np = n(2);
  th = (pi / 2) * ((0:nh-1).' / (nh - 1)) .^ 2;
  ps = pi * (0:np-1).' / (np - 1);
  ## every node at once: theta_h fastest, as the lookup indexes the table
  [TH, PS] = ndgrid (th, ps);
  N = cos (TH(:)) .* H + sin (TH(:)) .* (cos (PS(:)) .* T + sin (PS(:)) .* B);
  ti = min (acos (min (max (N * L.', -1), 1)), pi / 2 - 1e-6);
  to = min (acos (min (max (N * V.', -1), 1)), pi / 2 - 1e-6);
  ## divided by cos (ti), which the lookup multiplies back exactly
  R = scene_slice (scene, material, ti, to, "pairs") ./ cos (ti);
  Rm = single (reshape (R, nh * np, 3));
  sl = struct ("H", H, "T", T, "B", B, "nh", nh, "np", np);
endfunction

## The bilinear weights of the slice table's entries at unit normals N
## (m x 3): what the trace cache keeps of a hit (the same for every material).
function w = slice_weights (sl, N)
  th = acos (min (max (N * sl.H.', -1), 1));
  ps = atan2 (abs (N * sl.B.'), N * sl.T.');
  nh = sl.nh;
  np = sl.np;
  fi = min (sqrt (th / (pi / 2)) * (nh - 1), nh - 1);
  fj = min (max (ps / pi * (np - 1), 0), np - 1);
  i0 = min (floor (fi), nh - 2);
  j0 = min (floor (fj), np - 2);
  w = struct ("a", single (fi - i0), "b", single (fj - j0), "k", int32 (i0 + 1 + j0 * nh), "nh", nh);
endfunction

## the radiance of lit samples from the slice table RM: the table
## interpolated with their weights W (slice_weights), times cos ti, COSI.
## The oct-file __rt_slice__ makes the same operations, compiled, when it
## is built; this code is the definition and the reference
function rad = slice_rad (Rm, w, cosi)
  [done, rad] = __lafortune_oct_call__ ("__rt_slice__", "rt_render", Rm, w.a, w.b, w.k, w.nh,
                                        cosi);
  if (! done)
    rad = double (slice_lookup (Rm, w)) .* cosi;
  endif
endfunction

## the table RM interpolated with the weights W of slice_weights
function v = slice_lookup (Rm, w)
  a = w.a;
  b = w.b;
  k = double (w.k);
  nh = w.nh;
  v = ((1 - a) .* (1 - b)) .* Rm(k,:) + (a .* (1 - b)) .* Rm(k+1,:) ...
      + ((1 - a) .* b) .* Rm(k+nh,:) + (a .* b) .* Rm(k+nh+1,:);
endfunction

%!shared lam, s
%! lam = struct ("rho_d", [0.8 0.5 0.2], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]);
%! s = scene_make ("sphere", "size", [24 32], "spp", 1);

%!test
%! ## the samples do not depend on how many rays are traced at once
%! sc = scene_make ("sphere", "size", [24 12], "spp", 3);
%! m = struct ("rho_d", [0.2 0.2 0.2], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);
%! assert (rt_render (sc, m, "chunk", 100, "progress", false),
%!         rt_render (sc, m, "progress", false), 1e-12);

%!test
%! ## Lambertian sphere: closed form per pixel at the pixel centres
%! [img, info] = rt_render (s, lam, "jitter", false, "progress", false);
%! assert (info.mode, "slice");
%! [img2, info2] = rt_render (s, lam, "jitter", false, "progress", false, "mode", "direct");
%! assert (info2.mode, "direct");
%! ext = s.camera.extent; H = s.height; W = s.width;
%! [c, r] = meshgrid (0:W-1, 0:H-1);
%! x = ((c + 0.5) / W - 0.5) * ext * W / H;
%! y = (0.5 - (r + 0.5) / H) * ext;
%! in = x .^ 2 + y .^ 2 < 1;
%! z = sqrt (max (1 - x .^ 2 - y .^ 2, 0));
%! ndl = max ([x(:) y(:) z(:)] * s.light.direction', 0);
%! ex = reshape ((ndl .* in(:)) .* lam.rho_d / pi, H, W, 3);
%! assert (img2, ex, -1e-6);
%! assert (img, ex, -1e-6);
%! assert (img(! in), zeros (nnz (! in), 1));

%!test
%! ## same seed, same image; another seed, another image
%! a = rt_render (s, lam, "progress", false);
%! b = rt_render (s, lam, "progress", false);
%! s2 = s; s2.seed = 2;
%! c = rt_render (s2, lam, "progress", false);
%! assert (isequal (a, b));
%! assert (! isequal (a, c));
%! assert (img_psnr (a, c) > 20);

%!test
%! ## trace once, shade many: the cached render is the full render, bit for bit
%! sc = scene_make ("spheres", "size", [20 30], "spp", 3);
%! m = struct ("rho_d", [0.2 0.3 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 40 50]);
%! [a, ia, C] = rt_render (sc, lam, "chunk", 500, "progress", false);
%! assert (! ia.cached && ! isempty (C));
%! [b, ib] = rt_render (sc, m, "cache", C, "chunk", 500, "progress", false);
%! assert (ib.cached);
%! assert (ib.rays, ia.rays);
%! [~, ~, C2] = rt_render (sc, m, "cache", C, "chunk", 500, "progress", false);
%! assert (isequal (C2, C));
%! assert (isequal (b, rt_render (sc, m, "chunk", 500, "progress", false)));
%! assert (isequal (a, rt_render (sc, lam, "cache", C, "chunk", 500, "progress", false)));
%! ## the measured data too
%! brdf = merl_standin ("red-plastic");
%! assert (isequal (rt_render (sc, brdf, "cache", C, "chunk", 500, "progress", false),
%!                  rt_render (sc, brdf, "chunk", 500, "progress", false)));
%! ## a background is shaded from the cache too
%! sb = sc; sb.background = [0.1 0.2 0.3];
%! [~, ~, Cb] = rt_render (sb, lam, "progress", false);
%! assert (isequal (rt_render (sb, m, "cache", Cb, "progress", false), rt_render (sb, m, "progress", false)));
%! ## a last chunk of one sample (chunk 47 of 48 samples: a miss) and of
%! ## two (chunk 23), traced and from the cache
%! sq = scene_make ("sphere", "size", [6 4]);
%! sq.spp = 2;
%! for ch = [47 23]
%!   [a, ~, C] = rt_render (sq, m, "chunk", ch, "progress", false);
%!   assert (isequal (a, rt_render (sq, m, "cache", C, "chunk", ch, "progress", false)));
%!   assert (all (isfinite (a(:))) && nnz (a) > 0);
%! endfor
%! ## direct mode keeps no cache
%! [~, ~, Cd] = rt_render (scene_make ("sphere", "size", 6, "camera", "perspective"), lam, "progress", false);
%! assert (isempty (Cd));
%!error <same scene and options> 
%! sc = scene_make ("sphere", "size", [8 8], "spp", 1);
%! lam = struct ("rho_d", [0.8 0.5 0.2], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]);
%! [~, ~, C] = rt_render (sc, lam, "progress", false);
%! sc.seed = 5;
%! rt_render (sc, lam, "cache", C, "progress", false);
%!error <same scene and options>
%! sc = scene_make ("sphere", "size", [8 8], "spp", 1);
%! lam = struct ("rho_d", [0.8 0.5 0.2], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]);
%! [~, ~, C] = rt_render (sc, lam, "progress", false);
%! rt_render (sc, lam, "cache", C, "chunk", 7, "progress", false);
%!error id=lafortune:badOption rt_render (scene_make ("sphere", "size", 4), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), "cache", struct ("x", 1))
%!error <rt_render: the model is unbounded: channel 1, lobe 1, reaches about 1e130> rt_render (scene_make ("sphere", "size", 4), struct ("rho_d", [0 0 0], "Cxy", [-1.5 0 0], "Cz", [0.9 0 0], "e", [738 1 1]))
%!test
%! ## the largest model that passes renders finite pixels from every side
%! m = struct ("rho_d", [0 0 0], "Cxy", [-1.5 0 0], "Cz", [0.9 0 0], "e", [170 1 1]);
%! for L = {[0 1 1], [0 1 -1], [1 0 -0.05], [0 -0.2 -1]}
%!   img = rt_render (scene_make ("sphere", "size", 24, "light_direction", L{1}), m, "progress", false);
%!   assert (all (isfinite (img(:))));
%! endfor
%!error <CACHE serves slice mode .* and lights mode> rt_render (scene_make ("sphere", "size", 4, "camera", "perspective"), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), "cache", struct ("key", 1, "chunks", {{}}))
%!error <Invalid call> rt_render (1)
%!error id=lafortune:badMaterial rt_render (scene_make ("sphere", "size", 4), struct ("foo", 1))
%!error id=lafortune:badMaterial rt_render (scene_make ("sphere", "size", 4), 42)
%!error id=lafortune:badScene rt_render (struct ("a", 1), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []))
%!error id=lafortune:badOption rt_render (scene_make ("sphere", "size", 4, "camera", "perspective"), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), "mode", "slice")
%!error id=lafortune:badOption rt_render (scene_make ("sphere", "size", 4), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), "mode", "fast")

%!demo
%! ## a Lafortune fit and its measured material side by side (stand-in data)
%! brdf = merl_standin ("green-metallic-paint");
%! s = scene_make ("spheres", "size", [160 240], "spp", 4);
%! [img, info] = rt_render (s, brdf);
%! imshow (min (img / prctile (img(:), 99.5), 1) .^ (1/2.2));
%! title (sprintf ("%s, %s mode, %.1f s", brdf.name, info.mode, info.time_total));
