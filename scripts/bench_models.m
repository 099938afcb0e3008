## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_models: fit time per model type and lobe count (brdf_fit, growing
## 1 -> 3 lobes in one call: the time to k lobes is cumulative, from
## info.lobe_time, summed over the channels) on the in-plane table (the
## paper's) and the scene table (the 512 x 256 sphere at 4 samples per
## pixel, relative weights) of the two paper materials, beside lafortune_fit ("lafortune"); with the error of
## each fit on its table (rmse for the in-plane table, the relative rmse
## that the scene fit minimises for the scene table) and its largest
## albedo.  Prints tables; not a test.  Run: make bench

1;
here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
addpath (here);
warning ("off", "Octave:shadowed-function");
warning ("off", "lafortune:notConverged");
pkg load optim;
mats = {"green-metallic-paint", "red-plastic"};
types = brdf_model ();
sc = scene_make ("sphere", "size", [512 256], "spp", 4);
for i = 1:numel (mats)
  [~, brdf, src] = bench_data (mats{i}, @() merl_standin (mats{i}), "built-in Cook-Torrance stand-in");
  tabs = {"inplane", merl_plane(brdf); "scene", merl_scene(brdf, sc)};
  for t = 1:rows (tabs)
    S = tabs{t,2};
    printf ("\nbench_models: %s, %s table (%d samples), %s\n", mats{i}, tabs{t,1}, rows (S.wi), src);
    printf ("%-17s | %-26s | %-30s | %-6s\n", "model", "time (s): 1, 2, 3 lobes",
            "error (mean RGB): 1, 2, 3 lobes", "albedo");
    base = [];
    for k = 1:numel (types)
      alb = NaN;
      [m, info, ms] = brdf_fit (S, types{k}, 3);
      tt = sum (info.lobe_time, 2).';            # the channels one after the other
      if (strcmp (tabs{t,1}, "scene"))
        err = cellfun (@(m) mean (brdf_error (m, S, info.weight)), ms);
      else
        err = mean (info.history, 2).';
      endif
      if (isfield (info, "albedo"))
        alb = max (info.albedo);
      endif
      if (isempty (base))
        base = tt;
      endif
      printf ("%-17s | %7.2f %7.2f %7.2f  (x%4.1f) | %9.4g %9.4g %9.4g | %6.3g\n", types{k}, tt,
              tt(3) / base(3), err, alb);
    endfor
  endfor
endfor
printf ("\n(xN: the 3-lobe fit's time over lafortune_fit's, in the same run; albedo: the largest\n");
printf ("directional albedo of the 3-lobe fit over R, G, B and the incidences, NaN for Lafortune)\n");
