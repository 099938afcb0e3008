## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_fit: in-plane 1/2/3-lobe RGB fits of green-metallic-paint, the
## paper's setup (leasqr defaults: finite-difference Jacobian, stol 1e-4,
## 20 iterations, no bounds, plain start) against this toolbox's fit
## (analytic Jacobian, bounds, grown deterministic start), and merl_eval
## throughput.  Prints tables; not a test.  Run: make bench

1;
here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
warning ("off", "Octave:shadowed-function");
warning ("off", "lafortune:notConverged");
addpath (here);
proxy = bench_data ("green-metallic-paint");
if (! isempty (proxy))
  brdf = merl_read (proxy);
  src = ["stand-in file " proxy];
else
  brdf = merl_standin ("green-metallic-paint");
  src = "built-in Cook-Torrance stand-in (../shared absent)";
endif
S = merl_plane (brdf);
printf ("bench_fit: %s, in-plane table of %d samples (grazing > 80 deg left out)\n\n", src, rows (S.wi));

printf ("Fit: time (s, all 3 channels) and rmse (mean over RGB); (b) grows 1->k, time is cumulative\n");
printf ("%-6s | %-10s %-10s | %-10s %-10s | %-7s %-9s\n", "lobes", "(a) time", "(a) rmse", ...
        "(b) time", "(b) rmse", "speedup", "rmse b/a");
reps = 3;
for k = 1:3
  ta = tb = Inf;
  for r = 1:reps
    tic; [ma, ia] = lafortune_fit (S, k, "init", "plain", "jacobian", "numeric", ...
                                   "tol", 1e-4, "max_iter", 20, "bounds", false); ta = min (ta, toc);
    tic; [mb, ib] = lafortune_fit (S, k); tb = min (tb, toc);
  endfor
  printf ("%-6d | %-10.3f %-10.4g | %-10.3f %-10.4g | %-7.1f %-9.3f\n", k, ta, mean (ia.rmse), ...
          tb, mean (ib.rmse), ta / tb, mean (ib.rmse) / mean (ia.rmse));
endfor

## stiff synthetic ground truth: where the plain start fails
printf ("\nStiff synthetic ground truth (noise free, in-plane at 0.5 deg): relative rmse, green channel\n");
printf ("%-40s | %-10s %-8s | %-10s %-8s\n", "truth", "(a) relrms", "(a) s", "(b) relrms", "(b) s");
cases = {struct("name", "1 lobe, e = 1e3", "Cxy", -1, "Cz", 1, "e", 1e3), ...
         struct("name", "1 lobe, e = 1e4", "Cxy", -1, "Cz", 1, "e", 1e4), ...
         struct("name", "2 lobes, e = 300 and 5", "Cxy", [-1; -0.7], "Cz", [1; 0.75], "e", [300; 5]), ...
         struct("name", "3 lobes, e = 2000, 40 and 3 (retro)", "Cxy", [-1; -0.9; 0.6], "Cz", [1; 0.9; 0.6], "e", [2000; 40; 3])};
[TI, TO] = ndgrid (0:0.5:80, -80:0.5:80);
wi = [sind(TI(:)) 0*TI(:) cosd(TI(:))];
wo = [sind(TO(:)) 0*TO(:) cosd(TO(:))];
for i = 1:numel (cases)
  t = cases{i};
  m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", repmat (t.Cxy, 1, 3), "Cz", repmat (t.Cz, 1, 3), ...
              "e", repmat (t.e, 1, 3));
  St = struct ("wi", wi, "wo", wo, "rgb", lafortune_eval (m, wi, wo));
  k = numel (t.e);
  tic; [~, ia] = lafortune_fit (St, k, "init", "plain", "jacobian", "numeric", ...
                                "tol", 1e-4, "max_iter", 20, "bounds", false, "channels", 2); ta = toc;
  tic; [~, ib] = lafortune_fit (St, k, "channels", 2); tb = toc;
  printf ("%-40s | %-10.3g %-8.2f | %-10.3g %-8.2f\n", t.name, ia.rel_rmse(2), ta, ib.rel_rmse(2), tb);
endfor

printf ("\nmerl_eval throughput (nearest bin, 1e6 random direction pairs)\n");
n = 1e6;
rand ("seed", 1);
u = rand (n, 2); v = rand (n, 2);
wi = [sqrt(1 - u(:,1).^2) .* cos(2*pi*u(:,2)), sqrt(1 - u(:,1).^2) .* sin(2*pi*u(:,2)), u(:,1)];
wo = [sqrt(1 - v(:,1).^2) .* cos(2*pi*v(:,2)), sqrt(1 - v(:,1).^2) .* sin(2*pi*v(:,2)), v(:,1)];
t = Inf;
for r = 1:3
  tic; merl_eval (brdf, wi, wo); t = min (t, toc);
endfor
tl = Inf;
for r = 1:3
  tic; merl_eval (brdf, wi, wo, "linear"); tl = min (tl, toc);
endfor
printf ("%-10s | %-10s | %-12s\n", "method", "time (s)", "lookups/s");
printf ("%-10s | %-10.3f | %-12.3g (target >= 5e6)\n", "nearest", t, n / t);
printf ("%-10s | %-10.3f | %-12.3g\n", "linear", tl, n / tl);
