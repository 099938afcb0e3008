## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_metrics: what judging a fit as a viewer sees it costs, and what
## shared lobes cost.  (1) img_flip (HDR-FLIP at its default exposures),
## img_deltae (CIEDE2000 and ITP) and img_psnr on a 256 x 512 render pair
## (the sphere scene's measured render and a 2-lobe in-plane fit's), beside
## the time of one render of that size, median of 5 runs; and 12 fits
## compared with one reference at once (img_compare's cell form: the
## reference's part made once), the cost of one more fit.  (2) Fits of
## lobes shared across R, G, B against separate per-channel fits, 1/2/3
## lobes, on the in-plane and scene tables of both paper materials: time
## and the rmse (mean over RGB), median of 3 runs.  Prints tables; not a
## test.  Run: make bench

1;

here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
addpath (here);
warning ("off", "Octave:shadowed-function");
warning ("off", "lafortune:notConverged");
pkg load optim;

function t = median_time (f, n)
  t = zeros (1, n);
  for i = 1:n
    t0 = tic (); f (); t(i) = toc (t0);
  endfor
  t = median (t);
endfunction

[~, brdf, src] = bench_data ("green-metallic-paint", @() merl_standin ("green-metallic-paint"),
                             "built-in Cook-Torrance stand-in");
scene = scene_make ("sphere", "size", [512 256], "spp", 4);
m2 = lafortune_fit (merl_plane (brdf), 2);
t0 = tic (); ref = rt_render (scene, brdf, "progress", false); trender = toc (t0);
img = rt_render (scene, m2, "progress", false);
printf ("bench_metrics: %s; sphere scene 512 x 256 (H x W), rt_render, 4 spp\n\n", src);
printf ("Image comparisons of one 512 x 256 pair (median of 5 runs)\n");
printf ("%-34s | %-8s | %-9s | %s\n", "measure", "s", "/ render", "value");
rows_ = {"img_psnr", @() img_psnr (ref, img);
         "img_flip (HDR, default exposures)", @() img_flip (ref, img);
         "img_flip (LDR)", @() img_flip (double (img_tonemap (ref, "auto")) / 255, ...
                                         double (img_tonemap (img, "auto")) / 255, "ldr", true);
         "img_deltae (CIEDE2000)", @() img_deltae (ref, img);
         "img_deltae (ITP)", @() img_deltae (ref, img, "metric", "itp");
         "img_compare (all of them)", @() img_compare (ref, img)};
for i = 1:rows (rows_)
  f = rows_{i,2};
  v = f ();
  vs = "";
  if (isnumeric (v) && isscalar (v))
    vs = sprintf ("%.4g", v);
  endif
  t = median_time (f, 5);
  printf ("%-34s | %-8.3f | %-9.3f | %s\n", rows_{i,1}, t, t / trender, vs);
endfor
printf ("%-34s | %-8.3f | %-9.3f |\n", "rt_render of the measured data", trender, 1);

## one reference, many fits: img_compare (ref, {img1, ...}) makes the
## reference's part once; the cost of one more fit is the slope
imgs = {img};
for k = [1 3]
  imgs{end+1} = rt_render (scene, lafortune_fit (merl_plane (brdf), k), "progress", false);
endfor
imgs = repmat (imgs, 1, 4);           # 12 fits
t1 = median_time (@() img_compare (ref, imgs(1)), 5);
t12 = median_time (@() img_compare (ref, imgs), 5);
printf ("\nOne reference, several fits: img_compare (ref, {img1, ..., imgN}), median of 5 runs\n");
printf ("%-34s | %-8s | %s\n", "fits compared", "s", "s per fit");
printf ("%-34s | %-8.3f | %.3f\n", "1", t1, t1);
printf ("%-34s | %-8.3f | %.3f\n", "12", t12, t12 / 12);
printf ("%-34s | %-8s | %.3f (target <= 0.1 s at 512 x 256: %s)\n", "one more fit (slope)", "", ...
        (t12 - t1) / 11, merge ((t12 - t1) / 11 <= 0.1, "met", "NOT met"));

printf ("\nShared lobes against separate channels: fit time (s, all 3 channels, grown 1->k) and rmse (mean RGB)\n");
printf ("%-22s | %-8s | %-5s | %-9s %-10s | %-9s %-10s | %-7s %-7s\n", "material", "table", "lobes", ...
        "sep. s", "sep. rmse", "shared s", "sh. rmse", "time", "rmse");
printf ("%-22s | %-8s | %-5s | %-9s %-10s | %-9s %-10s | %-7s %-7s\n", "", "", "", "", "", "", "", ...
        "sh/sep", "sh/sep");
sc = scene_make ("sphere", "size", [128 64], "spp", 1);
for mat = {"green-metallic-paint", "red-plastic"}
  [~, b] = bench_data (mat{1}, @() merl_standin (mat{1}), "");
  T = struct ("inplane", merl_plane (b), "scene", merl_scene (b, sc));
  for tn = {"inplane", "scene"}
    w = "plain";
    if (strcmp (tn{1}, "scene"))
      w = "psnr";
    endif
    S = T.(tn{1});
    for k = 1:3
      [~, is] = lafortune_fit (S, k, "weight", w);
      [~, ih] = lafortune_fit (S, k, "weight", w, "color", "shared");
      ts = median_time (@() lafortune_fit (S, k, "weight", w), 3);
      th = median_time (@() lafortune_fit (S, k, "weight", w, "color", "shared"), 3);
      printf ("%-22s | %-8s | %-5d | %-9.3f %-10.4g | %-9.3f %-10.4g | %-7.2f %-7.3f\n", mat{1}, tn{1}, k, ...
              ts, mean (is.rmse), th, mean (ih.rmse), th / ts, mean (ih.rmse) / mean (is.rmse));
    endfor
  endfor
endfor
