## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{scene} =} repro_scene (@var{c})
## The one scene of `make reproduce`: the paper's Happy Buddha when MESH
## names its PLY file, else the built-in scene SCENE (default "sphere": one
## sphere, every orientation of the surface once, as a lit-sphere view);
## orthographic camera and directional light, the paper's 256 x 512 size
## (smaller when QUICK).
## @end deftypefn
function scene = repro_scene (c)
  if (! isempty (c.mesh))
    scene = scene_make ("mesh", "file", c.mesh, "size", c.size, "spp", c.spp);
  elseif (strcmp (c.scene, "torus"))
    scene = scene_make ("torus", "resolution", c.torus, "size", c.size, "spp", c.spp);
  else
    scene = scene_make (c.scene, "size", c.size, "spp", c.spp);
  endif
endfunction
