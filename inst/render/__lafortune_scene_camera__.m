## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{cam} =} __lafortune_scene_camera__ (@var{scene})
## The one camera of the package (private): the frame of the camera of a
## scene struct that @code{scene_check} accepted.  Fields @code{type},
## @code{eye}, @code{f} (unit, viewing direction), @code{r} (unit, image
## right), @code{u} (unit, image up), @code{w}, @code{h} (orthographic: world
## width and height of the view; perspective: width and height of the image
## at unit distance along @code{f}), @code{W}, @code{H} (pixels).
##
## A point of the view at x, y (x from -0.5 at the left edge to 0.5 at the
## right, y from -0.5 at the bottom to 0.5 at the top) is seen along the ray
## from eye + x w r + y h u along f (orthographic) or from eye along
## f + x w r + y h u (perspective); @code{camera_rays} makes those rays.
## Pixel (row i, column j, 1-based) covers x in [(j-1)/W, j/W] - 0.5 and
## y in 0.5 - [i/H, (i-1)/H].
## @end deftypefn
function cam = __lafortune_scene_camera__ (scene)
  c = scene.camera;
  W = H = 1;                            # (scene_slice needs no image size)
  if (isfield (scene, "width"))
    W = scene.width;
    H = scene.height;
  endif
  eye = double (c.eye(:)');
  f = double (c.target(:)') - eye;
  f /= norm (f);
  r = cross (f, double (c.up(:)'));
  r /= norm (r);
  u = cross (r, f);
  if (strcmp (c.type, "orthographic"))
    h = double (c.extent);
  else
    h = 2 * tand (double (c.fov) / 2);
  endif
  cam = struct ("type", c.type, "eye", eye, "f", f, "r", r, "u", u,
                "w", h * W / H, "h", h, "W", W, "H", H);
endfunction
