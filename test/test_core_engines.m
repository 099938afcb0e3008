## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## The model's two engines give the same bits.  The private lafortune_core
## (the one evaluation of the model) calls the oct-file __lafortune_core__
## when it is built and otherwise does the arithmetic itself, in Octave; that
## Octave arithmetic is the reference.  Here the oct-file is hidden by taking
## its folder off the path, and values (lafortune_eval) and whole fits
## (lafortune_fit, which uses the Jacobian at every iteration) are compared
## with isequal, on ordinary, stiff and extreme models.

%!function varargout = __octave_engine (fn)
%!  ## FN () with the oct-file __lafortune_core__ off the path
%!  d = fileparts (which ("__lafortune_core__"));
%!  assert (! isempty (d), "the oct-file __lafortune_core__ is not built (make -C src)");
%!  assert (! strcmp (d, fileparts (which ("lafortune_eval"))),
%!          "the oct-file shares its folder with the m-files; it cannot be hidden");
%!  old = path ();
%!  ## every path entry that is that folder (as given, maybe relative)
%!  dirs = strsplit (old, pathsep ());
%!  hide = dirs(strcmp (cellfun (@canonicalize_file_name, dirs, "UniformOutput", false),
%!                      canonicalize_file_name (d)));
%!  unwind_protect
%!    rmpath (hide{:});
%!    assert (exist ("__lafortune_core__", "file"), 0);
%!    [varargout{1:nargout}] = fn ();
%!  unwind_protect_cleanup
%!    path (old);
%!  end_unwind_protect
%!  assert (exist ("__lafortune_core__", "file"), 3);
%!endfunction

%!function [wi, wo] = __dirs (n)
%!  ## N direction pairs over the hemisphere, deterministic
%!  t = (1:n)' / (n + 1);
%!  ti = acos (1 - 0.98 * t); to = acos (1 - 0.98 * mod (7 * t, 1));
%!  pi_ = 2 * pi * mod (3 * t, 1); po = 2 * pi * mod (11 * t, 1);
%!  wi = [sin(ti) .* cos(pi_), sin(ti) .* sin(pi_), cos(ti)];
%!  wo = [sin(to) .* cos(po), sin(to) .* sin(po), cos(to)];
%!endfunction

%!test
%! ## values: ordinary, sharp, capped (exp(300)), e = 0, tiny bases,
%! ## retro-reflective lobes, no lobe
%! [wi, wo] = __dirs (3000);
%! wi(1,:) = wo(1,:) = [0 0 1];
%! wo(2,:) = [-wi(2,1:2) wi(2,3)];             # the mirror direction
%! z = zeros (1, 3);
%! M = {struct("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -0.9 -1.1], "Cz", [1 0.8 0.95], "e", [10 20 5]), ...
%!      struct("rho_d", z, "Cxy", [-1 -1 -1; 1 2 3], "Cz", [1 1 1; 0.5 0.5 0.5], "e", [1e4 1e6 1e7; 0 0.5 2]), ...
%!      struct("rho_d", [1 1 1], "Cxy", [-5 -50 -500], "Cz", [5 50 500], "e", [200 400 1e5]), ...
%!      struct("rho_d", z, "Cxy", [-1e-200 1e-200 0], "Cz", [1e-200 1e-200 1e-300], "e", [3 50 1]), ...
%!      struct("rho_d", [0.5 0 0.25], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3))};
%! for k = 1:numel (M)
%!   fc = lafortune_eval (M{k}, wi, wo);
%!   fo = __octave_engine (@() lafortune_eval (M{k}, wi, wo));
%!   assert (isequal (fc, fo), sprintf ("model %d: the engines differ", k));
%!   assert (all (isfinite (fc(:))));
%! endfor

%!test
%! ## whole fits, so Jacobians too: noisy 2-lobe data, 1 to 3 lobes, the plain
%! ## and the log metric, the grown and the plain start
%! warning ("off", "lafortune:notConverged", "local");
%! [wi, wo] = __dirs (2500);
%! m0 = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-1 -1 -1.05; -0.6 -0.7 -0.5],
%!              "Cz", [1 0.95 1; 0.3 0.4 0.2], "e", [40 25 60; 3 4 2]);
%! S.wi = wi; S.wo = wo;
%! S.rgb = lafortune_eval (m0, wi, wo) .* (1 + 0.05 * sin (97 * (1:2500)'));
%! cases = {{2, "weight", "plain"}, {3, "weight", "log"}, {1, "init", "plain"}};
%! for k = 1:numel (cases)
%!   a = cases{k};
%!   [mc, ic] = lafortune_fit (S, a{:});
%!   [mo, io] = __octave_engine (@() lafortune_fit (S, a{:}));
%!   assert (isequal (mc, mo), sprintf ("case %d: the models differ", k));
%!   assert (isequal (ic.rmse, io.rmse) && isequal (ic.iterations, io.iterations),
%!           sprintf ("case %d: the fits differ", k));
%! endfor

%!test
%! ## a stiff fit: exact data of a sharp lobe (e = 2000), tiny values
%! warning ("off", "lafortune:notConverged", "local");
%! [wi, wo] = __dirs (2000);
%! m0 = struct ("rho_d", 1e-9 * [1 2 3], "Cxy", -1.001 * [1 1 1], "Cz", [1 1 1],
%!              "e", [2000 1500 2500]);
%! S.wi = wi; S.wo = wo; S.rgb = 1e-6 * lafortune_eval (m0, wi, wo);
%! [mc, ic] = lafortune_fit (S, 1);
%! [mo, io] = __octave_engine (@() lafortune_fit (S, 1));
%! assert (isequal (mc, mo));
%! assert (isequal (ic.rmse, io.rmse));
