## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{scene} =} repro_scene (@var{c})
## @deftypefnx {} {@var{scene} =} repro_scene (@var{c}, @var{name}, @var{value}, @dots{})
## The one scene of `make reproduce`: the paper's Happy Buddha when MESH
## names its PLY file, else the built-in scene SCENE (default "sphere": one
## sphere, every orientation of the surface once, as a lit-sphere view);
## orthographic camera and directional light, the paper's 256 x 512 size
## (smaller when QUICK).  Further scene_make options replace the light or
## the samples (the held-out scenes of repro_judge).
## @end deftypefn
function scene = repro_scene (c, varargin)
  if (! isempty (c.mesh))
    scene = scene_make ("mesh", "file", c.mesh, "size", c.size, "spp", c.spp, varargin{:});
  elseif (strcmp (c.scene, "torus"))
    scene = scene_make ("torus", "resolution", c.torus, "size", c.size, "spp", c.spp, varargin{:});
  else
    scene = scene_make (c.scene, "size", c.size, "spp", c.spp, varargin{:});
  endif
endfunction
