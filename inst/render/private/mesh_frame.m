## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{eye}, @var{target}, @var{extent}, @var{fov}] =} mesh_frame (@var{lo}, @var{hi}, @var{aspect})
## A camera on +z that frames the box [@var{lo}, @var{hi}] (private, for
## scene_make).  The camera looks along -z at the box centre, y up, from 5
## half-extents of the box (its largest half side) away, so always from
## outside the box.  @var{extent} (orthographic: world height of the view) and
## @var{fov} (perspective: vertical field of view, degrees) leave a margin of
## 10% around the box for the image shape @var{aspect} = height / width: the
## orthographic view holds the box's x-y rectangle, the perspective one the
## box's front face (the frustum only widens behind it, and the box's section
## is the same at every depth, so it holds the whole box).
## @end deftypefn
function [eye, target, extent, fov] = mesh_frame (lo, hi, aspect)
  target = (lo + hi) / 2;
  h = (hi - lo) / 2;                         # half sides
  dist = 5 * max (h);
  eye = target + [0 0 dist];
  extent = 1.1 * max (2 * h(2), 2 * h(1) * aspect);
  fov = 2 * atand (1.1 * max (h(2), h(1) * aspect) / (dist - h(3)));
endfunction
