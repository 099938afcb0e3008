## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## Integration tests of the error metrics (brdf_error, the private
## metric_spec) with the quadrature weights of merl_samples.  Run from the
## package root with
##   addpath ("inst"); test ("test/test_metrics.m")

%!function p = __proxy (name)
%!  d = getenv ("MERL_PROXY_DIR");
%!  if (isempty (d))
%!    d = fullfile (pwd (), "..", "shared", "data", "merl-proxy");
%!  endif
%!  p = fullfile (d, [name ".binary"]);
%!  if (! exist (p, "file"))
%!    printf ("skipped: %s absent\n", p);
%!    p = "";
%!  endif
%!endfunction


%!test
%! ## "psnr" of a scene table is img_psnr of the images it stands for: an
%! ## image whose pixels each see one angle pair (and a black background),
%! ## also after merging the pixels that see the same pair
%! m = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-1 -1 -1], "Cz", [0.9 0.9 0.9], "e", [20 40 60]);
%! ref = struct ("rho_d", [0.25 0.1 0.04], "Cxy", [-1 -1 -1], "Cz", [0.92 0.92 0.92], "e", [25 35 50]);
%! [ti, to] = ndgrid (0:5:75, [-75:5:-5 5:5:75]);
%! wi = [sind(ti(:)) 0*ti(:) cosd(ti(:))];
%! wo = [sind(to(:)) 0*to(:) cosd(to(:))];
%! ## 24 x 40 pixels: every pair once, a third of them twice, the rest background
%! np = 960;
%! k = [(1:rows (wi))'; (1:3:rows (wi))'];
%! E = [1.5 1.2 1.0];                     # the light's irradiance, per channel
%! L = zeros (np, 3); Lm = zeros (np, 3);
%! L(1:numel (k),:) = lafortune_eval (ref, wi(k,:), wo(k,:)) .* wi(k,3) .* E;
%! Lm(1:numel (k),:) = lafortune_eval (m, wi(k,:), wo(k,:)) .* wi(k,3) .* E;
%! db = img_psnr (reshape (L, 24, 40, 3), reshape (Lm, 24, 40, 3));
%! cnt = accumarray (k, 1);
%! S = struct ("kind", "scene", "wi", wi, "wo", wo, "rgb", lafortune_eval (ref, wi, wo),
%!             "weight", cnt / np, "irradiance", wi(:,3) .* E);
%! assert (brdf_error (m, S, "psnr"), db, 1e-10);
%! assert (db > 10 && db < 60);

%!test
%! ## the weights make the errors integrals: a table of 20000 samples drawn
%! ## by max_samples gives the errors of all 925000 bins (the data's
%! ## highlight makes "plain" and "cosine" the least stable)
%! truth = struct ("rho_d", [0.05 0.1 0.02], "Cxy", [-1 -1 -1; -0.7 -0.7 -0.7], ...
%!                 "Cz", [1 1 1; 0.72 0.72 0.72], "e", [200 200 200; 8 8 8]);
%! b = merl_synth (truth);
%! m = struct ("rho_d", [0.06 0.12 0.03], "Cxy", -[1 1 1], "Cz", [0.97 0.97 0.97], "e", [60 60 60]);
%! S = merl_samples (b, "views", false);
%! Sm = merl_samples (b, "max_samples", 20000, "views", false);
%! tol = struct ("plain", 0.05, "cosine", 0.05, "relative", 0.01, "log", 0.01, "cuberoot", 0.01);
%! for name = fieldnames (tol)'
%!   e = brdf_error (m, S, name{1});
%!   em = brdf_error (m, Sm, name{1});
%!   assert (em, e, tol.(name{1}) * e);
%! endfor

%!test
%! ## the fitter's reported errors are the metrics' (unweighted in-plane table)
%! truth = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-1 -1 -1; -0.6 -0.6 -0.6], ...
%!                 "Cz", [1 1 1; 0.65 0.65 0.65], "e", [60 60 60; 4 4 4]);
%! b = merl_synth (truth, "noise", 0.05);
%! S = merl_plane (b, "step", 2);
%! [m, info] = lafortune_fit (S, 1);
%! assert (brdf_error (m, S, "plain"), info.rmse, 1e-12);
%! assert (brdf_error (m, S, "cosine"), info.cos_rmse, 1e-12);
%! assert (brdf_error (m, S, "log"), info.log_rmse, 1e-12);

%!test
%! ## stiff: exponent 1e5, data over ten decades with zeros: finite metrics
%! m = struct ("rho_d", [0 1e-6 0], "Cxy", -[1.001 1.001 1.001], "Cz", [1 1 1], "e", 1e5 * [1 1 1]);
%! t = (0:0.25:80)';
%! S = struct ("wi", [sind(t) 0*t cosd(t)], "wo", [-sind(t) 0*t cosd(t)]);
%! S.rgb = lafortune_eval (m, S.wi, S.wo) .* (1 + 0.1 * cos (t));
%! S.rgb(1:4:end,:) = 0;
%! assert (max (S.rgb(:)) > 1e10 * min (S.rgb(S.rgb > 0)));
%! for name = {"plain", "cosine", "relative", "log", "cuberoot"}
%!   e = brdf_error (m, S, name{1});
%!   assert (all (isfinite (e) & e >= 0), name{1});
%! endfor

%!test
%! ## the MERL-format stand-ins with Ngan et al.'s published 1-lobe fits:
%! ## 20000 drawn samples give the hemisphere's errors
%! fits = {"green-metallic-paint", lafortune_ngan([0.015, 0.0537, 0.0428], [0.22, 0.217, 0.153], -0.591, 0.548, 76);
%!         "red-plastic", lafortune_ngan([0.28, 0.0496, 0.0139], [0.25, 0.198, 0.134], -0.63, 0.453, 23.2)};
%! for i = 1:rows (fits)
%!   p = __proxy (fits{i,1});
%!   if (isempty (p))
%!     continue;
%!   endif
%!   b = merl_read (p);
%!   S = merl_samples (b, "views", false);
%!   Sm = merl_samples (b, "max_samples", 20000, "views", false);
%!   for name = {"plain", "cosine", "relative", "log", "cuberoot"}
%!     e = brdf_error (fits{i,2}, S, name{1});
%!     em = brdf_error (fits{i,2}, Sm, name{1});
%!     assert (all (isfinite (e) & e > 0));
%!     assert (em, e, 0.05 * e);
%!   endfor
%! endfor
