## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_env: environment light in both renderers.  Three tables:
##  1. error against run time: the measured data (green-metallic-paint's
##     stand-in) and its 2-lobe Lafortune fit on the sphere under the light
##     probe courtyard (the built-in sky without blender-data), one ray per
##     pixel centre, 1 to 256 light samples per pixel against a 4096-sample
##     render: time and FLIP (img_compare);
##  2. what K costs in POV-Ray: the map cut into K = 16 ... 1024 directional
##     lights (scene_lights), the fit rendered by POV-Ray (pov_render: the
##     scene's tables, POV-Ray's time) and by rt_render with the same lights;
##     FLIP of each against rt_render's sampled map (the 4096-sample
##     render), and POV-Ray against rt_render on the same lights;
##  3. shading from the cache: a fit rendered from the measured data's
##     trace at 512 x 256 with 256 light samples per pixel: BRDF evaluations
##     per second (material_x, the compiled model core for Lafortune fits)
##     and for the whole cached render, per model.
## Prints tables; not a test.  Run: make bench, or
##   octave-cli --path src scripts/bench_env.m [quick]
## ("quick": smaller images and K up to 128, for a smoke run).

1;
here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
addpath (here);
warning ("off", "Octave:shadowed-function");
warning ("off", "lafortune:noLightProbe");
args = argv ();
quick = ! isempty (args) && strcmp (args{end}, "quick");
pkg load optim

b = merl_standin ("green-metallic-paint");
proxy = bench_data ("green-metallic-paint");
if (! isempty (proxy))
  b = merl_read (proxy);
endif
fit = lafortune_fit (merl_samples (b), 2);
n1 = 128;
Ks = [16 32 64 128 256 512 1024];
ref_ns = 4096;
if (quick)
  n1 = 48;
  Ks = [16 32 64 128];
  ref_ns = 1024;
endif
[~, cores] = system ("nproc");
s = scene_make ("sphere", "size", n1, "spp", 1, "jitter", false, "light", "environment",
                "map", "courtyard");
printf ("bench_env: %s and its 2-lobe Lafortune fit, sphere %d x %d, light probe %s; Octave %s, %s cores\n\n",
        b.name, n1, n1, s.light.name, version (), strtrim (cores));

## 1. error against run time, light samples
printf ("1. Light samples per pixel against a %d-sample render (rt_render, one ray per pixel centre)\n\n", ref_ns);
printf ("%-9s %7s | %9s %7s %9s\n", "material", "samples", "time (s)", "FLIP", "PSNR (dB)");
printf ("%s\n", repmat ("-", 1, 48));
mats = {b, fit};
names = {"measured", "fit"};
refs = cell (1, 2);
for m = 1:2
  s.seed = 1;
  [refs{m}, ir] = rt_render (s, mats{m}, "progress", false, "light_samples", ref_ns);
  for ns = [1 4 16 64 256]
    s.seed = 100 + ns;
    [img, info] = rt_render (s, mats{m}, "progress", false, "light_samples", ns);
    q = img_compare (refs{m}, img);
    printf ("%-9s %7d | %9.3f %7.3f %9.2f\n", names{m}, ns, info.time_total, q.flip, q.psnr);
  endfor
  printf ("%-9s %7d | %9.3f %7s %9s\n", names{m}, ref_ns, ir.time_total, "(ref)", "");
endfor

## 2. K lights: POV-Ray's cost and error
printf ("\n2. The map as K directional lights (median cut), the fit: POV-Ray (tables and render) and rt_render\n");
printf ("   FLIP against rt_render's %d-sample render of the map; POV-Ray against rt_render on the same K lights\n\n", ref_ns);
printf ("%5s | %9s %9s %9s | %8s %8s | %8s %7s\n", "K", "tables s", "POV-Ray s", "rt s",
        "FLIP pov", "FLIP rt", "pov-rt dB", "pov-rt FLIP");
printf ("%s\n", repmat ("-", 1, 84));
for K = Ks
  sl = scene_lights (s, K);
  t0 = tic ();
  [pimg, pinfo] = pov_render (sl, fit);
  [rimg, rinfo] = rt_render (sl, fit, "progress", false);
  qp = img_compare (refs{2}, pimg);
  qr = img_compare (refs{2}, rimg);
  qa = img_compare (rimg, pimg);
  printf ("%5d | %9.2f %9.2f %9.2f | %8.3f %8.3f | %8.1f %7.4f\n", K, pinfo.write_time,
          pinfo.time, rinfo.time_total, qp.flip, qr.flip, qa.psnr, qa.flip);
  fflush (stdout);
endfor

## 3. shading from the cache
W = 256; H = 512; ns = 256;
if (quick)
  W = 64; H = 128;
endif
printf ("\n3. Shading from the cache: %d x %d sphere, %d light samples per pixel, the trace of the measured data\n\n", W, H, ns);
c = scene_make ("sphere", "size", [H W], "spp", 1, "light", "environment", "map", "courtyard",
                "light_samples", ns);
[~, it, C] = rt_render (c, b, "progress", false);
printf ("trace and measured shading: %.2f s, %d lit light samples of %d\n\n", it.time_total,
        it.evaluations, H * W * ns);
fits = {fit, lafortune_fit(merl_samples (b), 1), lafortune_fit(merl_samples (b), 3), ...
        brdf_model("ggx", "rho_d", [0.01 0.05 0.04], "ks", [0.2; 0.05], "alpha", [0.05; 0.3], "F0", 0.5), b};
fnames = {"lafortune, 2 lobes", "lafortune, 1 lobe", "lafortune, 3 lobes", "ggx, 2 lobes", "measured (MERL)"};
printf ("%-20s | %12s %10s | %10s %12s\n", "material", "evaluations", "BRDF s", "BRDF M/s", "render M/s");
printf ("%s\n", repmat ("-", 1, 72));
for i = 1:numel (fits)
  [~, ic] = rt_render (c, fits{i}, "progress", false, "cache", C);
  printf ("%-20s | %12d %10.3f | %10.1f %12.1f\n", fnames{i}, ic.evaluations, ic.time_brdf,
          ic.evaluations / ic.time_brdf / 1e6, ic.evaluations / ic.time_total / 1e6);
  fflush (stdout);
endfor
