## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_render: the Octave raytracer at the paper's image size (256 x 512:
## W = 256, H = 512) with a MERL material, for the scenes "sphere", "spheres"
## and the built-in mesh "torus": render time at 1, 16 and 128 samples per
## pixel, rays per second, memory of what the shading used, and PSNR against
## a 256-spp reference rendered with another seed and per-sample MERL
## lookups (mode "direct": the material itself, no slice table), i.e. error
## against run time.  For the sphere, rows with mode "direct" show the
## per-sample lookups against the default 2-D slice.  The paper (pbrt, Happy Buddha,
## 256 x 512, 128 rays per pixel) took 345 s per image; the target here is
## the sphere at 128 spp well under that on a 2-core machine.
## Prints a table; not a test.  Run: make bench, or
##   octave-cli scripts/bench_render.m [quick]
## ("quick": 1/4 of the pixels and references at 64 spp, for a smoke run).

1;
function t = bvh_time (s)
  tic;
  rt_bvh (s.objects.vertices, s.objects.faces);
  t = toc;
endfunction

function s = ifelse_size (sz)
  if (ischar (sz))
    s = "256 x 512 (W x H, the paper's size)";
  else
    s = sprintf ("%d x %d (W x H, quick)", sz(2), sz(1));
  endif
endfunction

here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "inst"));
warning ("off", "Octave:shadowed-function");
args = argv ();
quick = ! isempty (args) && strcmp (args{end}, "quick");

addpath (here);
proxy = bench_data ("green-metallic-paint");
if (! isempty (proxy))
  brdf = merl_read (proxy);
  src = ["stand-in file " proxy];
else
  brdf = merl_synth (struct ("rho_d", [0.003 0.04 0.034], "Cxy", [-1 -1 -1], ...
                             "Cz", [0.95 0.95 0.95], "e", [60 60 60]), ...
                     "name", "synthetic green-metallic-like lobe");
  src = "merl_synth of a one-lobe Lafortune model (../shared absent)";
endif
full_bytes = numel (brdf.data) * 8;

sz = "paper";
ref_spp = 256;
if (quick)
  sz = [256 128];
  ref_spp = 64;
endif
[~, cores] = system ("nproc");
printf ("bench_render: %s\n", src);
printf ("Octave %s, %s cores; image %s, MERL table %.1f MB\n\n", version (), strtrim (cores), ...
        ifelse_size (sz), full_bytes / 1e6);

printf ("%-8s %-6s %5s | %9s %9s %11s %10s | %11s %9s\n", "scene", "mode", "spp", ...
        "time (s)", "rays", "rays/s", "material", "PSNR (dB)", "vs paper");
printf ("%s\n", repmat ("-", 1, 96));
rows_out = {};
for scn = {"sphere", "spheres", "torus"}
  s = scene_make (scn{1}, "size", sz, "spp", ref_spp, "seed", 1000);
  [ref, iref] = rt_render (s, brdf, "progress", false, "mode", "direct");
  runs = {"slice", 1; "slice", 16; "slice", 128; "direct", 16};
  if (strcmp (scn{1}, "sphere"))
    runs = [runs(1:3,:); {"direct", 1}; runs(4,:); {"direct", 128}];
  endif
  for k = 1:rows (runs)
    s.spp = runs{k,2};
    s.seed = 1;
    [img, info] = rt_render (s, brdf, "progress", false, "mode", runs{k,1});
    if (s.spp == 16)
      same.(runs{k,1}) = img;               # same samples in both modes
    endif
    printf ("%-8s %-6s %5d | %9.2f %9.3g %11.3g %8.0f kB | %11.2f %8.1f%%\n", scn{1}, ...
            info.mode, s.spp, info.time_total, info.rays, info.rays_per_second, ...
            info.material_bytes / 1e3, img_psnr (ref, img), 100 * info.time_total / 345);
    fflush (stdout);
  endfor
  printf ("%-8s %-6s %5d | %9.2f %9.3g %11.3g %8.0f kB | %11s  (reference)\n", scn{1}, ...
          iref.mode, ref_spp, iref.time_total, iref.rays, iref.rays_per_second, ...
          iref.material_bytes / 1e3, "-");
  printf ("%-8s slice against direct with the same 16 samples per pixel: %.2f dB\n", "", ...
          img_psnr (same.direct, same.slice));
  if (strcmp (scn{1}, "torus"))
    printf ("%-8s (%d triangles, BVH built in the setup time)\n", "", rows (s.objects.faces));
  endif
  fflush (stdout);
endfor
## a 100k-triangle mesh: the built-in torus at [224 224]
s = scene_make ("torus", "size", sz, "spp", 16, "resolution", [224 224]);
[img, info] = rt_render (s, brdf, "progress", false);
printf ("%-8s %-6s %5d | %9.2f %9.3g %11.3g %8.0f kB | %11s %8.1f%%\n", "torus", ...
        info.mode, s.spp, info.time_total, info.rays, info.rays_per_second, ...
        info.material_bytes / 1e3, "-", 100 * info.time_total / 345);
printf ("%-8s (%d triangles; BVH %.1f s of the setup %.1f s)\n", "", rows (s.objects.faces), ...
        bvh_time (s), info.time_setup);

printf ("\nPSNR: against the %d-spp direct-mode reference of the same scene (another seed),\n", ref_spp);
printf ("peak = the reference's maximum; it includes the reference's own noise and, for\n");
printf ("slice rows, the slice's difference from per-sample lookups (the line under each\n");
printf ("scene: the MERL nearest-bin lookup jumps at bin edges, the table interpolates).\n");
printf ("Timings are wall-clock on a shared machine: expect +-30 %%.\n");
printf ("vs paper: render time as a share of the paper's 345 s per 256 x 512 image at\n");
printf ("128 rays per pixel (pbrt, Happy Buddha).  Target: the sphere at 128 spp well under 345 s.\n");
printf ("material: the memory the shading used: the slice table (rt_render default) or\n");
printf ("the whole MERL struct (direct mode, %.1f MB of data).\n", full_bytes / 1e6);
