## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{S} =} merl_scene (@var{material}, @var{scene})
## @deftypefnx {lafortune} {@var{S} =} merl_scene (@var{material}, @var{scene}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{S}, @var{img}] =} merl_scene (@dots{})
## The table of BRDF samples that a scene's pixels see, weighted by their
## share of the image: what a fit must get right for that picture.
##
## @var{material} is a MERL material or an analytic model of any type (see
## @code{material_eval}); @var{scene} a scene struct from @code{scene_make}.
## The samples are the ones @code{rt_render} takes: the same stratified
## pixel samples (@code{scene.spp}, @code{scene.seed}, @code{scene.jitter}),
## cameras, intersections, normals and shadow rays (the private helpers
## both use).  Every sample that sees a lit surface gives an angle pair:
## ti = angle (N, L), to = angle (N, V) and gamma = angle (L, V), which fix
## an isotropic BRDF's value.  Samples are gathered into cells of
## @qcode{"bin"} degrees in (ti, to, gamma) (with an orthographic camera and
## a directional light gamma is one value: the cells are those of
## @code{scene_slice}'s 2-D slice), and each cell gives one row at its
## samples' mean angles.
##
## A sharp highlight can be narrower than a pixel: a few samples per pixel
## then miss it or hit its peak, and a cell's mean angle misses it too (a
## fit to such a table can render worse with more lobes).  So the pixels that may hold the mirror direction
## (N = H, halfway between L and V: the smallest angle (N, H) of their
## samples is below twice the angle between their mean normal and a
## neighbour's) are sampled again with @qcode{"refine"} samples each (fewer
## when that would more than double the samples), and each of
## those samples is a row of its own, at its exact angles.
##
## @var{S} is a scene table, as @code{brdf_error} and
## @code{lafortune_fit} take it:
## @table @code
## @item kind
## @qcode{"scene"}.
## @item wi, wo, rgb
## N x 3: local directions (built as @code{scene_slice} builds them) and the
## material's BRDF there.
## @item weight
## N x 1: the fraction of all the image's pixel samples in the cell (the
## sum is the lit fraction of the image's samples, <= 1); 0 where a MERL
## material's bin is missing (its value is unknown: the render, @var{img},
## shows it as 0, and a fit leaves it out).
## @item irradiance
## N x 3: the irradiance times cos ti there (the mean over the cell), so
## that a sample's radiance is @code{rgb .* irradiance}.
## @item peak
## the largest pixel of the image rendered from the table (@var{img}).
## @item name, scene, bin, samples
## the material's name, the scene's name, the cell size (degrees) and the
## number of pixel samples traced (refined pixels included).
## @item prior, prior_weight
## for a MERL material, the whole hemisphere (@code{merl_samples}, grazing
## angles beyond 80 degrees left out) and its weight in a fit (option
## @qcode{"prior"}, default 1e-4; 0: none).  @code{lafortune_fit} appends it
## with weights that sum to @code{prior_weight} times the table's own: one
## view fixes the angle gamma between light and viewer, where a lobe's base
## Cxy (ux vx + uy vy) + Cz uz vz is Cxy cos gamma + (Cz - Cxy) uz vz, so the
## scene determines only two of a lobe's three parameters; the prior
## settles the third (without it a fit may use Cxy = Cz and a huge exponent,
## a constant in this view that explodes in any other).  The prior's error
## per unit weight is far larger than the scene's (it holds the grazing
## angles the model fits worst), so a small weight already pulls hard (the
## README's "Measurements behind the design" gives the measurement behind
## the default).  A
## larger prior trades the scene's picture for other views.
## @end table
##
## A model's image error is then a weighted sum over the table: with one
## sample per pixel the image's MSE is sum (weight .* mean ((f - y) .*
## irradiance)^2, 2) up to the cells' width, and with more samples per
## pixel up to the averaging within pixels (@code{brdf_error (model, S,
## "psnr")}), so a weighted least-squares fit on @var{S} maximises the
## render's PSNR.  @var{img} is the scene rendered from the table (H x W x 3,
## background where nothing is hit).
##
## Options: @qcode{"bin"}, the cell size in degrees (default 0.25; smaller
## cells, more rows); @qcode{"refine"}, the samples per pixel where the
## mirror direction may be (default 256; 0 or at most @code{scene.spp}: no
## refinement); @qcode{"prior"} (above).
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## scene = scene_make ("sphere", "size", [64 64], "spp", 1);
## S = merl_scene (brdf, scene);
## m = lafortune_fit (S, 2);                    # the sphere's picture, fitted
## brdf_error (m, S, "psnr")                # about its render's PSNR
## @end group
## @end example
## @seealso{merl_samples, merl_plane, brdf_error, lafortune_fit, rt_render, scene_slice}
## @end deftypefn

function [S, img] = merl_scene (material, scene, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  __lafortune_scene_check__ (scene, "merl_scene");
  if (any (strcmp (scene.light.type, {"environment", "lights"})))
    error ("lafortune:badScene",
           "merl_scene: the table of a scene needs one directional or point light, got %s light (render it with rt_render; scene_lights gives its directional lights one by one)",
           scene.light.type);
  endif
  if (isempty (__lafortune_material_kind__ (material)))
    error ("lafortune:badMaterial",
           "merl_scene: MATERIAL must be a MERL material or an analytic model (brdf_model), got %s",
           class (material));
  endif
  opt = __lafortune_parse_opts__ (varargin, "merl_scene", struct ("bin", 0.25, "prior", 1e-4, "refine", 256));
  if (! (isnumeric (opt.bin) && isscalar (opt.bin) && opt.bin > 0 && opt.bin <= 10))
    error ("lafortune:badOption", "merl_scene: BIN must be a cell size in (0, 10] degrees");
  endif
  if (! (isnumeric (opt.refine) && isscalar (opt.refine) && opt.refine == fix (opt.refine)
         && opt.refine >= 0 && opt.refine <= 4096))
    error ("lafortune:badOption", "merl_scene: REFINE must be an integer number of samples from 0 to 4096");
  endif
  if (! (isnumeric (opt.prior) && isscalar (opt.prior) && opt.prior >= 0 && isfinite (opt.prior)))
    error ("lafortune:badOption", "merl_scene: PRIOR must be a finite weight >= 0");
  endif
  [objs, epsilon] = scene_setup (scene);
  cam = __lafortune_scene_camera__ (scene);
  H = scene.height;
  W = scene.width;
  npix = H * W;
  spp = scene.spp;
  total = npix * spp;
  jitter = scene_jitter (scene);

  ## every lit sample: its pixel, angles (ti, to, gamma), E cos ti and its
  ## share of the image; then the pixels that may hold the mirror direction
  ## again, with REFINE samples each (a sharp highlight can be smaller than
  ## a pixel, and a few samples miss or overstate it)
  state = rand ("state");
  unwind_protect
    rand ("state", scene.seed);
    [P, miss] = trace_pass (scene, objs, cam, epsilon, (0:total-1).', jitter, npix, 1 / total);
    ns = total;
    fine = refine_pixels (P, H, W);
    ## at most as many samples again as the first pass
    nref = min (opt.refine, floor (total / max (nnz (fine), 1)));
    if (nref > spp && any (fine))
      pf = find (fine) - 1;
      sr = scene;
      sr.spp = nref;
      k = reshape (pf.' + npix * (0:nref-1).', [], 1);
      [Pr, mr] = trace_pass (sr, objs, cam, epsilon, k, jitter, npix, 1 / (npix * nref));
      ns += numel (k);
      Pr(:,12) = 1:rows (Pr);          # each refined sample its own row
      P = [P(! fine(P(:,1)),:); Pr];
      miss = miss .* ! fine * (1 / spp) + mr / nref;
    else
      miss /= spp;
    endif
  unwind_protect_cleanup
    rand ("state", state);
  end_unwind_protect

  ## cells of BIN degrees in (ti, to, gamma); the refined pixels' samples
  ## are rows of their own (near the mirror direction theta_h grows as the
  ## square root of the distance to the edge of the reachable (ti, to), so
  ## a cell's mean angle would miss a narrow peak)
  c = [floor(P(:,2:4) / (opt.bin * pi / 180)), P(:,12)];
  [~, ~, cell_] = unique (c, "rows");
  n = max ([cell_; 0]);
  wgt = accumarray (cell_, P(:,8), [n 1]);
  mean_of = @(v) accumarray (cell_, v .* P(:,8), [n 1]) ./ max (wgt, realmin);
  ti = mean_of (P(:,2));
  to = mean_of (P(:,3));
  ga = mean_of (P(:,4));
  irr = [mean_of(P(:,5)), mean_of(P(:,6)), mean_of(P(:,7))];
  [wi, wo] = __lafortune_slice_dirs__ (ti, to, cos (ga));
  rgb = zeros (n, 3);
  known = true (n, 1);
  if (n > 0 && strcmp (__lafortune_material_kind__ (material), "merl"))
    ## a missing MERL bin renders as 0, but its value is unknown: no weight
    ## in a fit
    [rgb, known] = merl_eval (material, wi, wo);
  elseif (n > 0)
    rgb = material_eval (material, wi, wo);
  endif

  ## the image rendered from the table
  acc = zeros (npix, 3);
  rad = rgb .* irr;
  for ch = 1:3
    acc(:,ch) = accumarray (P(:,1), rad(cell_,ch) .* P(:,8) * npix, [npix 1]);
  endfor
  img = acc + miss .* double (scene.background(:).');
  img = reshape (img, H, W, 3);

  S = struct ("kind", "scene", "wi", wi, "wo", wo, "rgb", rgb, "weight", wgt .* known,
              "irradiance", irr, "peak", max (img(:)), "name", __lafortune_name_of__ (material), "scene", __lafortune_name_of__ (scene),
              "bin", opt.bin, "samples", ns, "prior", [], "prior_weight", 0);
  if (opt.prior > 0 && strcmp (__lafortune_material_kind__ (material), "merl"))
    S.prior = merl_samples (material, "max_angle", 80, "views", false);
    S.prior_weight = opt.prior;
  endif
endfunction

## The lit samples K (0-based sample numbers of SCENE's pixel samples) of
## one pass, each a share W of the image: rows [pixel, ti, to, gamma, E cos
## ti (1 x 3), W, normal (1 x 3), 0 (the row's own cell: 0 = by its
## angles)]; MISS (npix x 1) counts the samples that hit nothing, per pixel.
function [P, miss] = trace_pass (scene, objs, cam, epsilon, k, jitter, npix, w)
  chunk = 65536;
  P = cell (1, ceil (numel (k) / chunk));
  miss = zeros (npix, 1);
  q = 0;
  for k0 = 0:chunk:numel(k)-1
    kk = k(k0+1:min (k0 + chunk, numel (k)));
    [O, D] = sample_rays (scene, cam, kk, jitter);
    T = scene_trace (objs, scene, O, D, epsilon);
    miss += accumarray (mod (kk, npix) + 1, T.miss, [npix 1]);
    il = find (T.lit);
    N = T.Ns(il,:);
    ang = acos (min (max ([sum(N .* T.L(il,:), 2), sum(N .* T.V(il,:), 2), ...
                            sum(T.L(il,:) .* T.V(il,:), 2)], -1), 1));
    q += 1;
    pix = mod (kk(T.h(il)), npix) + 1;
    m = numel (il);
    P{q} = [pix(:), ang, T.E(il,:) .* T.cosi(il), w(ones (m, 1)), N, zeros(m, 1)];
  endfor
  P = vertcat (P{1:q}, zeros (0, 12));
endfunction

## The pixels (H x W logical, as a column) that may hold the mirror
## direction N = H: the smallest theta_h of their samples (half_angle) is
## below twice the largest angle between their mean normal and a lit
## neighbour's (the pixel's footprint in normals).  Their highlight can be
## narrower than the pixel.
function fine = refine_pixels (P, H, W)
  npix = H * W;
  Nm = zeros (npix, 3);
  for d = 1:3
    Nm(:,d) = accumarray (P(:,1), P(:,8+d), [npix 1]);
  endfor
  len = sqrt (sum (Nm .^ 2, 2));
  has = reshape (len > 0, H, W);
  Nm = reshape (Nm ./ max (len, realmin), H, W, 3);
  th = accumarray (P(:,1), __lafortune_half_angle__ (P(:,2), P(:,3), P(:,4)), [npix 1], @min, Inf);
  ## angles between vertical, then horizontal neighbours, where both are lit
  spread = zeros (H, W);
  a = acos (min (max (sum (Nm(1:end-1,:,:) .* Nm(2:end,:,:), 3), -1), 1)) .* (has(1:end-1,:) & has(2:end,:));
  spread(1:end-1,:) = max (spread(1:end-1,:), a);
  spread(2:end,:) = max (spread(2:end,:), a);
  a = acos (min (max (sum (Nm(:,1:end-1,:) .* Nm(:,2:end,:), 3), -1), 1)) .* (has(:,1:end-1) & has(:,2:end));
  spread(:,1:end-1) = max (spread(:,1:end-1), a);
  spread(:,2:end) = max (spread(:,2:end), a);
  fine = has(:) & th < 2 * spread(:);
endfunction

%!shared brdf, m2
%! brdf = merl_standin ("red-plastic");
%! m2 = struct ("rho_d", [0.2 0.05 0.02], "Cxy", -[0.8 0.8 0.8; 0.6 0.6 0.6],
%!              "Cz", [0.8 0.8 0.8; 0.5 0.5 0.5], "e", [40 40 40; 5 5 5]);

%!test
%! ## the table's own image is the render, and its PSNR the render's PSNR
%! sc = scene_make ("sphere", "size", [48 48], "spp", 1, "jitter", false);
%! [S, img] = merl_scene (m2, sc, "bin", 0.1);
%! assert (S.kind, "scene");
%! assert (size (S.wi, 2) == 3 && rows (S.wi) == rows (S.rgb) && rows (S.weight) == rows (S.wi));
%! assert (norm (S.wi, "rows"), ones (rows (S.wi), 1), 1e-12);
%! ref = rt_render (sc, m2, "mode", "direct", "progress", false);
%! assert (img_psnr (ref, img) > 45);
%! ## the lit share of the image: the sphere's lit disc over the square
%! assert (sum (S.weight), nnz (any (ref > 0, 3)) / 48^2, 1e-12);

%!test
%! ## the weighted table predicts a model's image error
%! sc = scene_make ("sphere", "size", [64 64], "spp", 1, "jitter", false);
%! S = merl_scene (brdf, sc);
%! ref = rt_render (sc, brdf, "mode", "direct", "progress", false);
%! img = rt_render (sc, m2, "mode", "direct", "progress", false);
%! assert (abs (brdf_error (m2, S, "psnr") - img_psnr (ref, img)) < 0.5);

%!test
%! ## perspective camera and shadows: gamma varies, cells in three angles
%! sc = scene_make ("spheres", "size", [32 32], "spp", 2, "camera", "perspective");
%! [S, img] = merl_scene (m2, sc, "bin", 1);
%! ga = acos (sum (S.wi .* S.wo, 2));
%! assert (max (ga) - min (ga) > 0.05);
%! assert (all (S.weight > 0) && sum (S.weight) < 1);
%! assert (all (S.irradiance(:) >= 0));
%! assert (img_psnr (rt_render (sc, m2, "mode", "direct", "progress", false), img) > 30);

%!test
%! ## a background shows where nothing is hit
%! sc = scene_make ("sphere", "size", [16 16], "spp", 1, "background", [1 2 3]);
%! [~, img] = merl_scene (m2, sc);
%! assert (squeeze (img(1,1,:))', [1 2 3]);

%!test
%! ## a highlight narrower than a pixel: the refined pixels catch its peak
%! ## and its share of the image, which 4 samples per pixel miss
%! sharp = struct ("rho_d", [1 1 1] * 1e-3, "Cxy", -[1 1 1], "Cz", [1 1 1], "e", [1 1 1] * 1e4);
%! sc = scene_make ("sphere", "size", [64 64], "spp", 4);
%! ref = rt_render (setfield (sc, "spp", 1024), sharp, "mode", "direct", "progress", false);
%! [S, img] = merl_scene (sharp, sc);
%! [S0, img0] = merl_scene (sharp, sc, "refine", 0);
%! assert (S.samples > S0.samples && S.samples < 2 * S0.samples);
%! assert (S.peak, max (ref(:)), 0.05 * max (ref(:)));       # measured: 0.6%
%! assert (S0.peak < 0.1 * max (ref(:)));                    # measured: 5%
%! assert (sum (S.weight), sum (S0.weight), 1e-12);
%! assert (img_psnr (ref, img) > img_psnr (ref, img0) + 20);  # measured: 65.0 and 32.9 dB

%!test
%! ## a missing MERL bin (merl_standin leaves out grazing angles) has no
%! ## weight: a fit leaves it out; the image still shows it as 0
%! b = merl_standin ("red-plastic");
%! [S, img] = merl_scene (b, scene_make ("sphere", "size", [32 32], "spp", 1));
%! [~, known] = merl_eval (b, S.wi, S.wo);
%! assert (any (! known));
%! assert (all (S.weight(! known) == 0));
%! assert (all (S.weight(known) > 0));
%! assert (all (S.rgb(! known,:)(:) == 0));

%!error id=lafortune:badScene merl_scene (merl_standin ("red-plastic"), scene_make ("sphere", "size", 4, "light", "environment", "map", "sky"))
%!error <Invalid call> merl_scene (1)
%!error id=lafortune:badScene merl_scene (struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), 1)
%!error id=lafortune:badMaterial merl_scene (42, scene_make ("sphere", "size", 4))
%!error id=lafortune:badOption merl_scene (struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3)), scene_make ("sphere", "size", 4), "bin", 0)
%!error id=lafortune:badOption merl_scene (struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3)), scene_make ("sphere", "size", 4), "prior", -1)
%!error id=lafortune:badOption merl_scene (struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3)), scene_make ("sphere", "size", 4), "refine", 1.5)

%!test
%! ## a MERL material's table carries the whole hemisphere as a prior, and the
%! ## fit made with it renders well in another view too
%! sc = scene_make ("sphere", "size", [48 48], "spp", 1, "jitter", false);
%! S = merl_scene (brdf, sc);
%! assert (S.prior_weight, 1e-4);
%! assert (rows (S.prior.wi) > 1e5);
%! m = lafortune_fit (S, 2, "weight", "psnr");
%! sb = sc; sb.light.direction = [1 0.3 0.6] / norm ([1 0.3 0.6]);
%! ref = rt_render (sb, brdf, "progress", false);
%! assert (img_psnr (ref, rt_render (sb, m, "progress", false)) > 30);
%! S0 = merl_scene (brdf, sc, "prior", 0);
%! assert (isempty (S0.prior) && S0.prior_weight == 0);

%!demo
%! ## which angle pairs the sphere's picture needs, and how much
%! brdf = merl_standin ("green-metallic-paint");
%! S = merl_scene (brdf, scene_make ("sphere", "size", [96 96], "spp", 1));
%! ti = acosd (S.wi(:,3)); to = acosd (S.wo(:,3));
%! scatter (to, ti, 8, log10 (S.weight), "filled");
%! xlabel ("angle (N, V), degrees"); ylabel ("angle (N, L), degrees");
%! title ("merl\\_scene: log10 of each angle pair's share of the image");
