## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## Integration tests of the fit on the MERL-format stand-ins beside the project
## (../shared/data/merl-proxy, or MERL_PROXY_DIR); each test skips with a
## message when they are absent.

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
%! ## the paper's in-plane fits: finite, never worse with more lobes, and the
%! ## growing fit no worse than leasqr from the paper's plain start
%! warning ("off", "lafortune:notConverged", "local");
%! for mat = {"green-metallic-paint", "red-plastic"}
%!   p = __proxy (mat{1});
%!   if (isempty (p))
%!     continue;
%!   endif
%!   S = merl_plane (merl_read (p));
%!   [m, info, models] = lafortune_fit (S, 3);
%!   assert (all (isfinite ([m.rho_d m.Cxy(:)' m.Cz(:)' m.e(:)'])));
%!   assert (all (all (diff (info.history) <= 1e-12)));
%!   for k = 1:3
%!     [~, ia] = lafortune_fit (S, k, "init", "plain", "jacobian", "numeric", ...
%!                              "tol", 1e-4, "max_iter", 20, "bounds", false);
%!     assert (all (info.history(k,:) <= ia.rmse * (1 + 1e-3)), ...
%!             sprintf ("%s, %d lobes: %s vs %s", mat{1}, k, mat2str (info.history(k,:)), mat2str (ia.rmse)));
%!   endfor
%! endfor

%!test
%! ## a hemisphere fit on a sparse subsample must not explode between samples
%! p = __proxy ("red-plastic");
%! if (! isempty (p))
%!   b = merl_read (p);
%!   S = merl_samples (b, "max_samples", 5000);
%!   [m, info] = lafortune_fit (S, 3);
%!   P = merl_plane (b, "step", 0.5);
%!   f = lafortune_eval (m, P.wi, P.wo);
%!   assert (all (isfinite (f(:))));
%!   assert (max (f) <= 10 * max (S.rgb));
%!   assert (max (info.rel_rmse) < 0.5);
%! endif
