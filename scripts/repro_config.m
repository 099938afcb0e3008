## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} repro_config ()
## Settings of `make reproduce`, from the environment that the Makefile sets:
## RESULTS (output folder), MERL_DIR (real MERL files), QUICK (1: classroom
## run under a minute), SCENE (built-in scene: sphere, the default, spheres
## or torus) and MESH (a PLY/OBJ file, e.g. the Happy Buddha, which then
## replaces the built-in scene).
## @end deftypefn
function c = repro_config ()
  c.results = getenv_default ("RESULTS", "results");
  c.merl_dir = getenv_default ("MERL_DIR", "data/merl");
  c.quick = str2double (getenv_default ("QUICK", "0")) == 1;
  c.mesh = getenv_default ("MESH", "");
  c.scene = getenv_default ("SCENE", "sphere");
  c.materials = {"green-metallic-paint", "red-plastic"};
  c.lobes = 1:3;
  c.max_angle = 80;             # grazing angles beyond this are left out
  ## the paper: 256 x 512 image, 128 rays per pixel
  c.paper_psnr = struct ("green_metallic_paint", [29.27 31.44 31.02],
                         "red_plastic", [28.12 27.56 27.81]);
  if (c.quick)
    c.size = [128 64];
    c.spp = 8;
    c.spp_study = [1 2 4];
    c.pov_aa = 2;
    c.hemi_samples = 5000;
    c.torus = [48 24];
  else
    c.size = [512 256];
    c.spp = 128;
    c.spp_study = [1 2 4 8 16 32 64];
    c.pov_aa = 4;
    c.hemi_samples = 40000;
    c.torus = [128 64];
  endif
endfunction

function v = getenv_default (name, def)
  v = getenv (name);
  if (isempty (v))
    v = def;
  endif
endfunction
