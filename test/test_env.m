## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## Environment light: scene_make's maps, rt_render's light samples against
## brute-force quadrature over the texels, scene_lights, and POV-Ray under
## the same list of lights.  Run from the package root with
##   addpath ("inst"); test ("test/test_env.m")

%!function m = models ()
%!  ## one moderate model of every type, and the built-in measured stand-in
%!  m = {struct("rho_d", [0.2 0.15 0.1], "Cxy", [-1 -1 -1], "Cz", [0.9 0.9 0.9], "e", [25 25 25]), ...
%!       brdf_model("blinnphong", "rho_d", [0.2 0.15 0.1], "ks", 0.5, "n", 30), ...
%!       brdf_model("ward", "rho_d", [0.2 0.15 0.1], "ks", 0.5, "alpha", 0.25), ...
%!       brdf_model("cooktorrance", "rho_d", [0.2 0.15 0.1], "ks", 0.5, "m", 0.3, "F0", 0.5), ...
%!       brdf_model("ggx", "rho_d", [0.2 0.15 0.1], "ks", 0.5, "alpha", 0.3, "F0", 0.5), ...
%!       brdf_model("ashikhminshirley", "rho_d", [0.2 0.15 0.1], "ks", 0.5, "n", 30, "F0", 0.5), ...
%!       merl_standin("red-plastic")};
%!endfunction

%!function M = smooth_map ()
%!  ## a small smooth map with a bright region, 8 x 16
%!  [c, r] = meshgrid ((0:15) + 0.5, (0:7) + 0.5);
%!  th = r / 8 * pi; ph = c / 16 * 2 * pi - pi;
%!  d = cat (3, sin (th) .* sin (ph), cos (th), -sin (th) .* cos (ph));
%!  s = [-0.5 0.6 0.62]; s /= norm (s);
%!  g = max (d(:,:,1) * s(1) + d(:,:,2) * s(2) + d(:,:,3) * s(3), 0) .^ 4;
%!  M = cat (3, 0.2 + 3 * g, 0.25 + 2.5 * g, 0.3 + 2 * g);
%!endfunction

%!function [D, E] = texel_lights (M, n)
%!  ## brute force: every texel cut into n x n parts, one light each, with
%!  ## the part's exact solid angle (an independent reading of the map's
%!  ## convention: row 1 up, centre column -z, columns toward +x)
%!  [H, W, ~] = size (M);
%!  D = zeros (H * W * n * n, 3); E = D; q = 0;
%!  for r = 1:H
%!    for sr = 1:n
%!      t0 = ((r - 1) + (sr - 1) / n) / H * pi; t1 = ((r - 1) + sr / n) / H * pi;
%!      tm = (t0 + t1) / 2;
%!      for c = 1:W
%!        for sc = 1:n
%!          p = ((c - 1) + (sc - 0.5) / n) / W * 2 * pi - pi;
%!          q += 1;
%!          D(q,:) = [sin(tm) * sin(p), cos(tm), -sin(tm) * cos(p)];
%!          E(q,:) = squeeze (M(r,c,:)).' * (2 * pi / W / n) * (cos (t0) - cos (t1));
%!        endfor
%!      endfor
%!    endfor
%!  endfor
%!endfunction

%!test
%! ## a Lambertian sphere under a constant map: every visible point sees the
%! ## whole sky, radiance rho L (the sphere casts no shadow on itself)
%! s = scene_make ("sphere", "size", 24, "spp", 1, "jitter", false, "light", "environment",
%!                 "map", 0.7 * ones (16, 32, 3), "light_samples", 1024);
%! lam = struct ("rho_d", [0.8 0.5 0.2], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! img = rt_render (s, lam, "progress", false);
%! in = img(:,:,1) > 0;
%! for c = 1:3
%!   v = img(:,:,c)(in);
%!   assert (mean (v), 0.7 * lam.rho_d(c), 2e-3 * lam.rho_d(c));
%!   assert (max (abs (v - 0.7 * lam.rho_d(c))), 0, 0.03 * lam.rho_d(c));
%! endfor
%! ## the intensity scales it, the rotation does not change it
%! s.light.irradiance = 2; s.light.rotation = 33;
%! img2 = rt_render (s, lam, "progress", false);
%! assert (mean (img2(:,:,2)(in)), 2 * 0.7 * 0.5, 2e-3);

%!test
%! ## every model type and the measured data converge to the brute-force
%! ## quadrature over every texel of a small map
%! M = smooth_map ();
%! s = scene_make ("sphere", "size", 12, "spp", 1, "jitter", false, "light", "environment",
%!                 "map", M, "light_samples", 4096);
%! [D, E] = texel_lights (M, 6);
%! b = scene_make ("sphere", "size", 12, "spp", 1, "jitter", false, "light", "lights",
%!                 "light_direction", D, "irradiance", E);
%! mm = models ();
%! for i = 1:numel (mm)
%!   ref = rt_render (b, mm{i}, "progress", false);
%!   img = rt_render (s, mm{i}, "progress", false);
%!   in = ref(:,:,1) > 0;
%!   err = sqrt (mean ((img(:) - ref(:)) .^ 2)) / mean (ref(in));
%!   assert (err < 0.01, "model %d: relative rms %.4f", i, err);
%!   ## and the sampled mean is unbiased: the image's sum within 0.5%
%!   assert (abs (sum (img(:)) / sum (ref(:)) - 1) < 5e-3, "model %d: sum", i);
%! endfor

%!test
%! ## the samples converge: 16 times the samples, about a quarter the error
%! M = smooth_map ();
%! mm = models ();
%! [D, E] = texel_lights (M, 6);
%! b = scene_make ("sphere", "size", 12, "spp", 1, "jitter", false, "light", "lights",
%!                 "light_direction", D, "irradiance", E);
%! ref = rt_render (b, mm{1}, "progress", false);
%! e = zeros (1, 2);
%! ns = [64 1024];
%! for j = 1:2
%!   s = scene_make ("sphere", "size", 12, "spp", 1, "jitter", false, "light", "environment",
%!                   "map", M, "light_samples", ns(j));
%!   img = rt_render (s, mm{1}, "progress", false);
%!   e(j) = sqrt (mean ((img(:) - ref(:)) .^ 2));
%! endfor
%! assert (e(1) / e(2) > 2.5 && e(1) / e(2) < 16);

%!test
%! ## shadow rays go into the scene's own geometry: the plane under the
%! ## spheres is darker under a sphere than in the open, and the spheres'
%! ## tops see more sky than their bottoms (the plane hides the lower sky)
%! s = scene_make ("spheres", "size", [48 64], "spp", 1, "jitter", false,
%!                 "light", "environment", "map", ones (8, 16, 3), "light_samples", 256);
%! lam = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! img = rt_render (s, lam, "progress", false);
%! g = img(:,:,2);
%! ## a plane point far from the spheres sees the upper half of the sky: rho L
%! assert (g(end, 1), 0.5, 0.03);
%! ## the contact shadow under the big sphere is much darker
%! assert (min (g(:)) < 0.25);
%! s.light.samples = 64;
%! [a, ia, C] = rt_render (s, lam, "progress", false);
%! m2 = brdf_model ("ggx", "rho_d", 0.1, "ks", 0.5, "alpha", 0.2, "F0", 0.9);
%! ## trace once, shade many: bit for bit the full render on the same
%! ## samples (the BRDF samples drawn from the cached render's density)
%! [b, ib] = rt_render (s, m2, "cache", C, "progress", false);
%! assert (ib.cached && ib.evaluations == ia.evaluations);
%! assert (isequal (ib.density, lam) && strcmp (ib.sampling, "mis"));
%! assert (isequal (b, rt_render (s, m2, "progress", false, "density", lam)));
%! assert (! isequal (b, rt_render (s, m2, "progress", false)));
%! assert (isequal (a, rt_render (s, lam, "cache", C, "progress", false)));
%! ## and the samples do not depend on how many rays are traced at once
%! assert (isequal (rt_render (s, m2, "chunk", 3000, "progress", false),
%!                  rt_render (s, m2, "progress", false)));

%!test
%! ## the measured data and every fit see the same light samples: a fit
%! ## rendered with the measured data's cache is the full render, and the
%! ## light_samples option overrides the scene's count
%! s = scene_make ("sphere", "size", 16, "spp", 2, "light", "environment", "map", "sky",
%!                 "light_samples", 8);
%! brdf = merl_standin ("green-metallic-paint");
%! [a, ia, C] = rt_render (s, brdf, "progress", false, "light_samples", 16);
%! assert (ia.light_samples, 16);
%! fit = models (){1};
%! assert (isequal (rt_render (s, fit, "cache", C, "progress", false, "light_samples", 16),
%!                  rt_render (s, fit, "progress", false, "light_samples", 16,
%!                             "density", ia.density)));
%! ## the measured data's density: a table of the data
%! assert (ia.density.sampler, "table");
%!error <same scene and options>
%! s = scene_make ("sphere", "size", 8, "spp", 1, "light", "environment", "map", "sky",
%!                 "light_samples", 8);
%! lam = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! [~, ~, C] = rt_render (s, lam, "progress", false);
%! rt_render (s, lam, "cache", C, "progress", false, "light_samples", 9);

%!test
%! ## POV-Ray under the same list of lights: every model type on the sphere
%! ## and on the spheres (cast shadows) agrees with rt_render to >= 50 dB and
%! ## FLIP <= 0.02, pixel centres against POV-Ray's one ray per pixel
%! [st, ~] = system ("command -v povray");
%! if (st != 0)
%!   printf ("skipped: POV-Ray is not installed\n");
%! else
%!   mm = models ();
%!   for n = {"sphere", "spheres"}
%!     s = scene_make (n{1}, "size", [40 56], "spp", 1, "jitter", false,
%!                     "light", "environment", "map", "sky");
%!     s = scene_lights (s, 6);
%!     for i = 1:numel (mm) - 1
%!       ref = rt_render (s, mm{i}, "progress", false);
%!       [img, info] = pov_render (s, mm{i});
%!       q = img_compare (ref, img);
%!       assert (info.frames, 6);
%!       assert (q.psnr >= 50 && q.flip <= 0.02, "%s, model %d: %.1f dB, FLIP %.4f", n{1}, i,
%!               q.psnr, q.flip);
%!     endfor
%!   endfor
%! endif

%!test
%! ## the measured data: POV-Ray's tables interpolate what rt_render looks up
%! ## bin by bin; lights from behind reach the rim, where the measured table
%! ## is roughest (README, "Environment light": under one directional light
%! ## the two renderers differ as much)
%! [st, ~] = system ("command -v povray");
%! if (st != 0)
%!   printf ("skipped: POV-Ray is not installed\n");
%! else
%!   b = models (){end};
%!   s = scene_lights (scene_make ("spheres", "size", [40 56], "spp", 1, "jitter", false,
%!                                 "light", "environment", "map", "sky"), 6);
%!   ref = rt_render (s, b, "progress", false);
%!   img = pov_render (s, b);
%!   q = img_compare (ref, img);
%!   assert (q.psnr >= 30 && q.flip <= 0.15, "%.1f dB, FLIP %.4f", q.psnr, q.flip);
%!   ## an environment scene goes to POV-Ray as K lights (option "lights")
%!   e = scene_make ("sphere", "size", [24 24], "spp", 1, "jitter", false,
%!                   "light", "environment", "map", "sky");
%!   m = models (){1};
%!   [img, info] = pov_render (e, m, "lights", 4);
%!   assert (info.frames, 4);
%!   q = img_compare (rt_render (scene_lights (e, 4), m, "progress", false), img);
%!   assert (q.psnr >= 50);
%!   ## the generated scene renders only as an animation, one frame a light
%!   d = tempname (); mkdir (d);
%!   unwind_protect
%!     f = fullfile (d, "s.pov");
%!     info = pov_write_scene (e, m, f, "lights", 3);
%!     assert (info.includes, {"s_L0001.inc", "s_L0002.inc", "s_L0003.inc"});
%!     assert (all (cellfun (@(g) exist (fullfile (d, g), "file") == 2, info.includes)));
%!     txt = fileread (f);
%!     assert (! isempty (strfind (txt, "+KFI1 +KFF3")));
%!     [st, out] = system (sprintf ("cd %s && povray +Is.pov +Oo.exr +FE +W24 +H24 -D -A 2>&1", d));
%!     assert (st != 0 || isempty (dir (fullfile (d, "o*.exr"))), "%s", out);
%!   unwind_protect_cleanup
%!     confirm_recursive_rmdir (false, "local");
%!     rmdir (d, "s");
%!   end_unwind_protect
%! endif

%!test
%! ## every scene renders under an environment: the torus (a mesh with
%! ## vertex normals, self-shadowing) and a perspective camera; the lit
%! ## pixels are finite and positive, the misses the background
%! m = models (){1};
%! for n = {"torus", "mesh", "spheres"}
%!   s = scene_make (n{1}, "size", [24 32], "spp", 1, "resolution", [16 8], "light", "environment",
%!                   "map", "sky", "light_samples", 16, "camera", "perspective",
%!                   "background", [0.1 0.2 0.3]);
%!   [img, info] = rt_render (s, m, "progress", false);
%!   assert (info.mode, "lights");
%!   assert (all (isfinite (img(:))) && all (img(:) >= 0));
%!   bg = all (abs (img - reshape ([0.1 0.2 0.3], 1, 1, 3)) < 1e-12, 3);
%!   assert (any (! bg(:)));
%!   assert (any (bg(:)) || strcmp (n{1}, "spheres"));      # the ground fills that view
%! endfor
%! ## the torus shadows itself: a Lambertian torus under a constant sky is
%! ## darker on its inner rim than the unoccluded rho L
%! s = scene_make ("torus", "size", [48 48], "spp", 1, "jitter", false, "resolution", [32 16],
%!                 "light", "environment", "map", ones (8, 16, 3), "light_samples", 256);
%! lam = struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! g = rt_render (s, lam, "progress", false)(:,:,2);
%! assert (max (g(:)) < 1.06 && max (g(:)) > 0.9);
%! assert (min (g(g > 0)) < 0.8);

%!test
%! ## multiple importance sampling: a white furnace (a constant map and a
%! ## white Lambertian sphere) gives 1 under every sampling, and an
%! ## energy-conserving model its directional albedo at each pixel's view
%! s = scene_make ("sphere", "size", 96, "spp", 1, "jitter", false, "light", "environment",
%!                 "map", ones (8, 16, 3), "light_samples", 64);
%! lam = struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! for smp = {"light", "brdf", "mis"}
%!   [img, info] = rt_render (s, lam, "sampling", smp{1}, "progress", false);
%!   assert (info.sampling, smp{1});
%!   g = img(:,:,2);
%!   assert (abs (mean (g(g > 0)) - 1) < 1e-3, sprintf ("%s: %g", smp{1}, mean (g(g > 0))));
%! endfor
%! m = brdf_model ("ggx", "rho_d", 0, "ks", 1, "alpha", 0.4, "F0", 1);
%! img = rt_render (s, m, "progress", false);
%! ## each pixel's view angle: the sphere's normal at its centre
%! H = s.height; ext = s.camera.extent;
%! [c, r] = meshgrid (0:H-1, 0:H-1);
%! x = ((c + 0.5) / H - 0.5) * ext; y = (0.5 - (r + 0.5) / H) * ext;
%! z = sqrt (max (1 - x .^ 2 - y .^ 2, 0));
%! in = z > 0.2;                           # away from the rim's partial pixels
%! a = brdf_albedo (m, acos (z(in)) * 180 / pi);
%! g = img(:,:,1);
%! assert (abs (mean (g(in)) / mean (a(:,1)) - 1) < 5e-3);

%!test
%! ## unbiased: the mean of the MIS render equals the light-only render's
%! ## within their standard errors, on a sharp Lafortune lobe, a GGX model
%! ## and the measured data (its density a table of its data); and on
%! ## the sharp lobe its noise is far smaller
%! s = scene_make ("sphere", "size", 64, "spp", 1, "light", "environment", "map", "sky",
%!                 "light_samples", 16);
%! mats = {struct("rho_d", [0.02 0.02 0.02], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [300 300 300]),
%!         brdf_model("ggx", "rho_d", [0.1 0.05 0.02], "ks", 1, "alpha", 0.15, "F0", 0.6),
%!         merl_standin("green-metallic-paint")};
%! for i = 1:3
%!   l = rt_render (s, mats{i}, "sampling", "light", "progress", false);
%!   m = rt_render (s, mats{i}, "progress", false);
%!   d = m(:) - l(:);
%!   se = std (d) / sqrt (numel (d));
%!   assert (abs (mean (d)) < 3 * se, sprintf ("material %d: %g, se %g", i, mean (d), se));
%! endfor
%! s2 = s; s2.seed = 2;
%! rel = @(smp) mean ((rt_render (s, mats{1}, "sampling", smp, "progress", false)(:)
%!                     - rt_render (s2, mats{1}, "sampling", smp, "progress", false)(:)) .^ 2);
%! assert (rel ("mis") < rel ("light") / 2);

%!test
%! ## the BRDF's share of the samples: about none for a diffuse material (a
%! ## Lambertian's density is the cosine, m2 = 1: the map's samples alone,
%! ## light sampling itself), about half for a sharp one, and any
%! ## share asked for (0.5: 0.11.0's split)
%! s = scene_make ("sphere", "size", 16, "spp", 1, "light", "environment", "map", "sky",
%!                 "light_samples", 16);
%! lam = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! [a, ia] = rt_render (s, lam, "progress", false);
%! assert (ia.brdf_share, 0);
%! l = rt_render (s, lam, "progress", false, "sampling", "light");
%! assert (isequal (a, l));            # light sampling itself, bit for bit
%! sharp = struct ("rho_d", [0.02 0.02 0.02], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [300 300 300]);
%! [~, ib] = rt_render (s, sharp, "progress", false);
%! assert (ib.brdf_share, 0.5);
%! [~, ih, C] = rt_render (s, lam, "progress", false, "brdf_share", 0.25);
%! assert (ih.brdf_share, 0.25);
%! [~, ic] = rt_render (s, sharp, "progress", false, "brdf_share", 0.25, "cache", C);
%! assert (ic.brdf_share, 0.25);

%!error id=lafortune:badOption
%! s = scene_make ("sphere", "size", 8, "light", "environment", "map", "sky");
%! rt_render (s, struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), "brdf_share", 2);
%!error <same scene and options>
%! s = scene_make ("sphere", "size", 8, "spp", 1, "light", "environment", "map", "sky", "light_samples", 8);
%! lam = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! [~, ~, C] = rt_render (s, lam, "progress", false);
%! rt_render (s, lam, "progress", false, "cache", C, "brdf_share", 0.5);
%!error id=lafortune:badOption
%! s = scene_make ("sphere", "size", 8, "light", "environment", "map", "sky");
%! rt_render (s, struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), "sampling", "bogus");
%!error <needs an environment light>
%! rt_render (scene_make ("sphere", "size", 8), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), "sampling", "mis");
