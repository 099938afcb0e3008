## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_merl: merl_eval's nearest-bin lookups per second against the MERL
## reference reader's arithmetic, in one run, at 1e4, 2e5, 1e6 and 4e6
## random direction pairs (uniform on the upper hemisphere):
##
##   merl_eval       the default method "nearest": the compiled lookup
##                   (src/__merl_nearest__.cc), a fast path plus the
##                   reader's arithmetic where rounding decides
##   reader, C++     __merl_nearest__ (..., "ref"): the reference reader's
##                   formulas (half vector, two Rodrigues rotations, index
##                   formulas) compiled, for every sample: this project's own
##                   C++ of the published formulas, not the reader's code
##   reader, Octave  merl_eval (..., "reference"): the same formulas
##                   vectorised in Octave (inst/merl/private/merl_index_ref.m),
##                   what merl_eval falls back to without the oct-file
##
## Times are medians of repeats interleaved round-robin (so load on a shared
## machine hits every method alike); ratios are reader time / merl_eval
## time.  "CPU" is merl_eval's lookups per second of process CPU time
## (cputime; single-threaded, so what a quiet machine gives in wall time).  Every run also checks that the three give the same bins for
## every pair.  Target (issue 10): merl_eval >= 5e6 lookups/s at every size.
## Prints a table; not a test.  Run: make bench, or
##   octave-cli --path src scripts/bench_merl.m [quick]

1;
function [wi, wo] = hemi_pairs (n)
  u = rand (n, 2); v = rand (n, 2);
  wi = [sqrt(1 - u(:,1).^2) .* cos(2*pi*u(:,2)), sqrt(1 - u(:,1).^2) .* sin(2*pi*u(:,2)), u(:,1)];
  wo = [sqrt(1 - v(:,1).^2) .* cos(2*pi*v(:,2)), sqrt(1 - v(:,1).^2) .* sin(2*pi*v(:,2)), v(:,1)];
endfunction

function s = ifelse_yes (c)
  if (c) s = "yes"; else s = "NO"; endif
endfunction

function s = ifelse_met (c)
  if (c) s = "met"; else s = "NOT met"; endif
endfunction

here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
addpath (here);
if (exist ("__merl_nearest__", "file") != 3)
  addpath (fullfile (here, "..", "src"));
endif
warning ("off", "Octave:shadowed-function");
args = argv ();
quick = ! isempty (args) && strcmp (args{end}, "quick");
if (exist ("__merl_nearest__", "file") != 3)
  printf ("bench_merl: skipped: the oct-file __merl_nearest__ is not built (make -C src)\n");
  return;
endif

[proxy, brdf, src] = bench_data ("green-metallic-paint", @() merl_standin ("green-metallic-paint"),
                                "merl_standin (\"green-metallic-paint\")");
sizes = [1e4 2e5 1e6 4e6];
if (quick)
  sizes = [1e4 2e5];
endif
printf ("bench_merl: %s\n", src);
printf ("Octave %s, %d cores; lookups/s (median of interleaved repeats), ratio = reader time / merl_eval time\n\n",
        version (), nproc ());
printf ("%9s | %12s %10s | %12s %7s | %12s %7s | %9s\n", "pairs", "merl_eval", "(CPU)",
        "reader C++", "ratio", "reader Oct", "ratio", "same bins");
printf ("%s\n", repmat ("-", 1, 96));
rand ("seed", 1);
worst = worst_cpu = Inf;
for n = sizes
  [wi, wo] = hemi_pairs (n);
  reps = max (3, min (25, round (2e6 / n)));
  t = zeros (reps, 3);
  tc = zeros (reps, 1);
  for r = 1:reps
    c0 = cputime (); tic; v1 = merl_eval (brdf, wi, wo); t(r,1) = toc; tc(r) = cputime () - c0;
    tic; v2 = __merl_nearest__ (brdf.data, brdf.valid, wi, wo, "ref"); t(r,2) = toc;
    tic; v3 = merl_eval (brdf, wi, wo, "reference"); t(r,3) = toc;
  endfor
  ## the bins themselves, on a table whose value is its own index
  idx.data = repmat ((1:1458000)', 1, 3);
  idx.valid = true (1458000, 1);
  b1 = merl_eval (idx, wi, wo)(:,1);
  [~, ~, b2] = __merl_nearest__ (idx.data, idx.valid, wi, wo, "ref");
  b3 = merl_eval (idx, wi, wo, "reference")(:,1);
  same = isequal (b1, b2, b3) && isequal (v1, v2, v3);
  m = median (t, 1);
  worst = min (worst, n / m(1));
  worst_cpu = min (worst_cpu, n / median (tc));
  printf ("%9d | %12.3g %10.3g | %12.3g %6.2fx | %12.3g %6.2fx | %9s\n", n, n / m(1),
          n / median (tc), n / m(2), m(2) / m(1), n / m(3), m(3) / m(1), ifelse_yes (same));
  fflush (stdout);
endfor
printf ("\nslowest merl_eval size: %.3g lookups/s wall, %.3g per CPU second (target >= 5e6: %s)\n",
        worst, worst_cpu, ifelse_met (worst >= 5e6));
printf ("Timings are wall clock on a shared machine; the ratios, measured in one run, are\n");
printf ("what to compare.  The linear method is not part of the target.\n");

