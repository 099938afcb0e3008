## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_pov: POV-Ray (pov_render) against the Octave raytracer (rt_render)
## on the same scenes, sizes and samples per pixel (time ratio, one run, and
## PSNR between them); then scene-file size and PSNR against the number of
## entries per pigment_map, evenly spaced and adaptive.  Prints tables; not a
## test.  Run: make bench   (or octave-cli --path src scripts/bench_pov.m)
##
## Environment: BENCH_POV_SIZE (default 256: images are N x N).

1;
here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
if (exist ("exrread") != 3)
  addpath (fullfile (here, "..", "src"));
endif
warning ("off", "Octave:shadowed-function");

N = 256;
if (! isempty (getenv ("BENCH_POV_SIZE")))
  N = str2double (getenv ("BENCH_POV_SIZE"));
endif

## Ngan et al.'s one-lobe green-metallic-paint fit (REFERENCE.md), their
## normalisation folded into Cxy and Cz per channel
rho_s = [0.22 0.217 0.153];
n = 76;
k = (rho_s * (n + 2) / (2 * pi)) .^ (1 / n) / 0.591;
gmp = struct ("name", "green-metallic-paint (Ngan 1-lobe)", "rho_d", [0.015 0.0537 0.0428],
              "Cxy", -0.591 * k, "Cz", 0.548 * k, "e", n * [1 1 1]);
## Lafortune et al. 1997's blue paint, 3 lobes
blue = struct ("name", "blue paint (Lafortune 1997, 3 lobes)", "rho_d", [0.3094 0.39667 0.70837] / pi,
               "Cxy", [0.870567 0.857255 0.670982; -0.451218 -0.406681 -0.477976;
                       -1.031545 -1.029426 -1.026588],
               "Cz", [0.803624 0.774290 0.586674; 0.023123 0.017625 0.227295;
                      0.706734 0.696530 0.687715],
               "e", [21.820103 18.597755 7.472717; 2.774499 2.581499 3.677653;
                     66.899060 63.767912 57.489181]);
## a sharp lobe
sharp = struct ("name", "sharp lobe (e = 2000)", "rho_d", [0.05 0.05 0.05], "Cxy", -[1 1 1],
                "Cz", [1 1 1], "e", 2000 * [1 1 1]);

[~, v] = system ("povray --version 2>&1 | grep -m1 'POV-Ray'");
printf ("bench_pov: %d x %d images, %s, Octave %s, %d cores\n", N, N, strtrim (v), version (),
        nproc ());
printf ("times are wall clock, one run each, on a shared machine\n\n");

## ---- 1. the two renderers on the same scene, size and spp
printf ("1. Renderers, %s\n", gmp.name);
printf ("   rt: rt_render (default mode: slice table); pov: pov_render = writing the scene + povray\n");
printf ("   spp 1: one ray through each pixel centre in both; spp 16: rt_render's 16 jittered\n");
printf ("   samples, POV-Ray's anti-aliasing +A0.0 +AM1 +R4 (4 x 4 rays where a pixel differs\n");
printf ("   from its neighbours)\n");
printf ("%-8s %4s | %8s %8s %8s %7s | %9s %9s | %10s\n", "scene", "spp", "rt s", "pov s",
        "(povray)", "rt/pov", "bytes", "entries", "PSNR rt/pov");
for sname = {"sphere", "spheres", "torus"}
  for spp = [1 16]
    sc = scene_make (sname{1}, "size", [N N], "spp", spp);
    t0 = tic ();
    ref = rt_render (sc, gmp, "jitter", spp > 1, "progress", false);
    trt = toc (t0);
    t0 = tic ();
    aa = 0;
    if (spp > 1)
      aa = 4;
    endif
    [img, info] = pov_render (sc, gmp, "antialias", aa);
    tpov = toc (t0);
    printf ("%-8s %4d | %8.2f %8.2f %8.2f %7.2f | %9d %9d | %8.1f dB\n", sname{1}, spp, trt, tpov,
            info.time, trt / tpov, info.bytes, info.entries, img_psnr (ref, img));
  endfor
endfor
printf ("\n");

## ---- 2. scene-file size and PSNR against entries per map
printf ("2. Table entries per map (each of the two levels) against the file and the image\n");
printf ("   PSNR against rt_render \"direct\" (the model evaluated at every pixel centre), spp 1\n");
printf ("   uniform: N entries evenly spaced; adaptive: N entries placed by refinement\n");
printf ("   (table_tol 0); default: adaptive with table_tol 1e-3, at most 256\n");
for c = {{"sphere", gmp}, {"spheres", blue}, {"sphere", sharp}}
  sc = scene_make (c{1}{1}, "size", [N N], "spp", 1);
  m = c{1}{2};
  ref = rt_render (sc, m, "jitter", false, "mode", "direct", "progress", false);
  slice = rt_render (sc, m, "jitter", false, "progress", false);
  printf ("\n   %s, %s (rt_render's own slice mode: %.1f dB)\n", c{1}{1}, m.name,
          img_psnr (ref, slice));
  printf ("%8s | %10s %8s | %10s %8s %8s\n", "entries", "uniform B", "PSNR", "adaptive B",
          "PSNR", "write s");
  for ne = [16 32 64 128 256]
    [iu, fu] = pov_render (sc, m, "entries", ne, "knots", "uniform");
    t0 = tic ();
    [ia, fa] = pov_render (sc, m, "entries", ne, "table_tol", 0);
    printf ("%8d | %10d %8.1f | %10d %8.1f %8.2f\n", ne, fu.bytes, img_psnr (ref, iu), fa.bytes,
            img_psnr (ref, ia), fa.write_time);
  endfor
  [id, fd] = pov_render (sc, m);
  printf ("%8s | %10s %8s | %10d %8.1f %8.2f\n", "default", "", "", fd.bytes, img_psnr (ref, id),
          fd.write_time);
endfor
