## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_fit: in-plane 1/2/3-lobe RGB fits of green-metallic-paint, the
## paper's setup (leasqr defaults: finite-difference Jacobian, stol 1e-4,
## 20 iterations, no bounds, plain start) against this toolbox's fit
## (analytic Jacobian, bounds, grown deterministic start); the same table,
## model and start fitted by scipy.optimize.least_squares (method "lm",
## MINPACK, analytic Jacobian, one thread; skipped when Debian's python3-scipy
## is absent) on both paper materials, median times;
## full-hemisphere fits on every valid bin, reduced to (a, c) cells, against
## the fit on all distinct (a, c) pairs; the model's compiled engine against
## its Octave arithmetic; and merl_eval throughput.  Prints tables; not a
## test.  Run: make bench

1;

## the python3 that has scipy (Debian's is /usr/bin/python3), or ""
function py = scipy_python ()
  py = "";
  for c = {"python3", "/usr/bin/python3"}
    [st, ~] = system (sprintf ("%s -c \"import scipy.optimize\" 2>/dev/null", c{1}));
    if (st == 0)
      py = c{1};
      return;
    endif
  endfor
endfunction

here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
warning ("off", "Octave:shadowed-function");
warning ("off", "lafortune:notConverged");
addpath (here);
[proxy, brdf, src] = bench_data ("green-metallic-paint", @() merl_standin ("green-metallic-paint"),
                                "built-in Cook-Torrance stand-in");
S = merl_plane (brdf);
printf ("bench_fit: %s, in-plane table of %d samples (grazing > 80 deg left out)\n\n", src, rows (S.wi));

printf ("Fit: time (s, all 3 channels) and rmse (mean over RGB); (b) grows 1->k, time is cumulative\n");
printf ("%-6s | %-10s %-10s | %-10s %-10s | %-7s %-9s\n", "lobes", "(a) time", "(a) rmse", ...
        "(b) time", "(b) rmse", "speedup", "rmse b/a");
reps = 3;
tb = rb = nan (1, 3);
for k = 1:3
  ta = Inf; tb(k) = Inf;
  for r = 1:reps
    tic; [ma, ia] = lafortune_fit (S, k, "init", "plain", "jacobian", "numeric", ...
                                   "tol", 1e-4, "max_iter", 20, "bounds", false); ta = min (ta, toc);
    tic; [mb, ib] = lafortune_fit (S, k); tb(k) = min (tb(k), toc);
  endfor
  rb(k) = mean (ib.rmse);
  printf ("%-6d | %-10.3f %-10.4g | %-10.3f %-10.4g | %-7.1f %-9.3f\n", k, ta, mean (ia.rmse), ...
          tb(k), rb(k), ta / tb(k), rb(k) / mean (ia.rmse));
endfor

## the model's two engines: lafortune_core calls the oct-file
## __lafortune_core__ when it is on the path, else does the same arithmetic
## in Octave; the same fits, timed with the oct-file's folder off the path
printf ("\nModel engines: (b) with the compiled lafortune_core (oct-file __lafortune_core__) against its Octave\n");
printf ("arithmetic (the oct-file's folder off the path); median of 5 interleaved, all 3 channels, s\n");
od = fileparts (which ("__lafortune_core__"));
if (isempty (od))
  printf ("skipped: the oct-file __lafortune_core__ is not built (make -C src)\n");
else
  ## every path entry that is the oct-file's folder (as given, maybe relative)
  dirs = strsplit (path (), pathsep ());
  hide = dirs(strcmp (cellfun (@canonicalize_file_name, dirs, "UniformOutput", false),
                      canonicalize_file_name (od)));
  printf ("%-6s | %-10s | %-10s | %-7s | %-9s\n", "lobes", "compiled", "Octave", "ratio", "same bits");
  for k = 1:3
    tcomp = toct = zeros (1, 5);
    for r = 1:5
      tic; mc = lafortune_fit (S, k); tcomp(r) = toc;
      old = path ();
      rmpath (hide{:});
      unwind_protect
        if (exist ("__lafortune_core__", "file"))
          error ("bench_fit: the oct-file __lafortune_core__ cannot be taken off the path");
        endif
        tic; mo = lafortune_fit (S, k); toct(r) = toc;
      unwind_protect_cleanup
        path (old);
      end_unwind_protect
    endfor
    printf ("%-6d | %-10.4f | %-10.4f | %-7.2f | %-9s\n", k, median (tcomp), median (toct),
            median (toct) / median (tcomp), {"NO", "yes"}{isequal (mc, mo) + 1});
  endfor
endif

## the peer: scipy's MINPACK on the same table, model and start, for both
## paper materials
printf ("\nPeer: scipy.optimize.least_squares (method \"lm\", MINPACK, analytic Jacobian), same table and model,\n");
printf ("from lafortune_fit's \"plain\" start, on one thread (OpenBLAS's second thread only spins here: scipy is\n");
printf ("faster without it); (c) lafortune_fit from that start; (b) lafortune_fit as above (grown start).\n");
preps = 5;
printf ("Times: median of %d, all 3 channels, wall-clock s (processor s); ratio = lafortune_fit / scipy; rmse: mean over RGB.\n", preps);
py = scipy_python ();
if (isempty (py))
  printf ("skipped: scipy is absent (install Debian's python3-scipy to compare; it is no dependency of lafortune)\n");
else
  for mat = {"green-metallic-paint", "red-plastic"}
    file = bench_data (mat{1});
    if (! isempty (file))
      Sp = merl_plane (merl_read (file));
      what = "stand-in file";
    else
      Sp = merl_plane (merl_standin (mat{1}));
      what = "built-in stand-in";
    endif
    printf ("%s (%s), %d samples\n", mat{1}, what, rows (Sp.wi));
    tab = [tempname() ".txt"];
    x = [Sp.wi(:,1) .* Sp.wo(:,1) + Sp.wi(:,2) .* Sp.wo(:,2), Sp.wi(:,3) .* Sp.wo(:,3)];
    fid = fopen (tab, "w");
    fprintf (fid, "%.17g %.17g %.17g %.17g %.17g\n", [x Sp.rgb].');
    fclose (fid);
    [st, out] = system (sprintf ("OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1 %s %s %s 3 %d",
                                 py, fullfile (here, "bench_fit_scipy.py"), tab, preps));
    unlink (tab);
    P = sscanf (out, "%f", [7 Inf]).';
    if (st != 0 || rows (P) != 3)
      printf ("skipped: the scipy peer failed: %s\n", out);
      continue;
    endif
    printf ("%-5s | %-15s %-9s | %-15s %-9s | %-15s %-9s | %-11s %-9s | %-11s %-9s\n", "lobes", "scipy s (cpu)", "rmse", ...
            "(c) s (cpu)", "rmse", "(b) s (cpu)", "rmse", "(c)/scipy", "rmse c/s", "(b)/scipy", "rmse b/s");
    lafortune_fit (Sp, 1);                  # warm: the first call loads optim
    for k = 1:3
      tc = tb = cc = cb = zeros (1, preps);
      for r = 1:preps
        t0 = tic (); c0 = cputime (); [~, ic] = lafortune_fit (Sp, k, "init", "plain");
        cc(r) = cputime () - c0; tc(r) = toc (t0);
        t0 = tic (); c0 = cputime (); [~, ib] = lafortune_fit (Sp, k);
        cb(r) = cputime () - c0; tb(r) = toc (t0);
      endfor
      tc = median (tc); tb = median (tb); cc = median (cc); cb = median (cb);
      rs = mean (P(k,3:5));
      printf ("%-5d | %-6.3f (%.3f) %-9.5g | %-6.3f (%.3f) %-9.5g | %-6.3f (%.3f) %-9.5g | %.2f (%.2f) %-9.6f | %.2f (%.2f) %-9.6f\n", ...
              k, P(k,2), P(k,7), rs, tc, cc, mean (ic.rmse), tb, cb, mean (ib.rmse), ...
              tc / P(k,2), cc / P(k,7), mean (ic.rmse) / rs, tb / P(k,2), cb / P(k,7), mean (ib.rmse) / rs);
    endfor
  endfor
endif

## every valid bin of the hemisphere: the fit on (a, c) cells against the
## fit on all distinct (a, c) pairs (exactly the fit on all samples)
H = merl_samples (brdf, "views", false);
printf ("\nHemisphere, every valid bin (%d samples), 3 lobes RGB: default reduction against the exact one\n", rows (H.wi));
printf ("%-14s | %-8s | %-8s | %-10s | %-12s\n", "reduction", "groups", "time s", "rmse", "rel. to exact");
tic; [me, ie] = lafortune_fit (H, 3, "reduce", "exact", "weight", "plain"); te = toc;
fe = lafortune_eval (me, H.wi, H.wo);
for red = {"auto", 256, 128}
  tic; [mg, ig] = lafortune_fit (H, 3, "reduce", red{1}, "weight", "plain"); tg = toc;
  fg = lafortune_eval (mg, H.wi, H.wo);
  printf ("%-14s | %-8d | %-8.2f | %-10.5g | %+.2e rmse, %.2e max |f - f_exact| / max f_exact; %.3fx time\n", ...
          ig.reduce, ig.groups, tg, mean (ig.rmse), mean (ig.rmse) / mean (ie.rmse) - 1, ...
          max (abs (fg(:) - fe(:))) / max (fe(:)), tg / te);
endfor
printf ("%-14s | %-8d | %-8.2f | %-10.5g |\n", ie.reduce, ie.groups, te, mean (ie.rmse));
proxy2 = bench_data ("red-plastic");
if (! isempty (proxy2))
  H2 = merl_samples (merl_read (proxy2), "views", false);
  tic; [~, i2] = lafortune_fit (H2, 3, "weight", "plain"); t2 = toc;
  printf ("red-plastic, every valid bin (%d samples), 3 lobes RGB, default (%s, %d groups): %.2f s, rmse %.5g\n", ...
          rows (H2.wi), i2.reduce, i2.groups, t2, mean (i2.rmse));
endif

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

