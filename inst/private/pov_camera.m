## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{cam} =} pov_camera (@var{scene}, @var{fname})
## Check @var{scene} and return its camera frame (private, for the
## @code{pov_*} functions): fields @code{type}, @code{eye}, @code{f} (unit,
## viewing direction), @code{r} (unit, image right), @code{u} (unit, image up),
## @code{w}, @code{h} (orthographic: world width and height of the view;
## perspective: width and height of the image at unit distance along
## @code{f}), @code{W}, @code{H} (pixels).  Pixel (row @var{i}, column
## @var{j}) has its centre at x = (@var{j} - 0.5)/W - 0.5, y = 0.5 - (@var{i} -
## 0.5)/H in units of the view, the ray through it starting at eye + x w r +
## y h u along f (orthographic) or at eye along f + x w r + y h u
## (perspective).  Errors @code{lafortune:badScene}.
## @end deftypefn
function cam = pov_camera (scene, fname)
  need = {"width", "height", "camera", "light", "objects"};
  if (! isstruct (scene) || ! isscalar (scene) || ! all (isfield (scene, need)))
    error ("lafortune:badScene", "%s: SCENE must be a scene struct from scene_make (fields %s)",
           fname, strjoin (need, ", "));
  endif
  W = scene.width;
  H = scene.height;
  if (! isscalar (W) || ! isscalar (H) || W < 1 || H < 1 || W != fix (W) || H != fix (H))
    error ("lafortune:badScene", "%s: SCENE.width and SCENE.height must be positive integers",
           fname);
  endif
  c = scene.camera;
  if (! isstruct (c) || ! all (isfield (c, {"type", "eye", "target", "up"})))
    error ("lafortune:badScene", "%s: SCENE.camera needs the fields type, eye, target, up",
           fname);
  endif
  eye = double (c.eye(:)');
  f = double (c.target(:)') - eye;
  if (numel (eye) != 3 || numel (f) != 3 || ! (norm (f) > 0))
    error ("lafortune:badScene", "%s: SCENE.camera.eye and .target must be distinct 3-vectors",
           fname);
  endif
  f /= norm (f);
  r = cross (f, double (c.up(:)'));
  if (! (norm (r) > 1e-12))
    error ("lafortune:badScene", "%s: SCENE.camera.up must not be parallel to the view direction",
           fname);
  endif
  r /= norm (r);
  u = cross (r, f);
  switch (c.type)
    case "orthographic"
      h = double (c.extent);
      if (! isscalar (h) || ! (h > 0))
        error ("lafortune:badScene", "%s: SCENE.camera.extent must be a positive scalar", fname);
      endif
    case "perspective"
      fov = double (c.fov);
      if (! isscalar (fov) || ! (fov > 0 && fov < 180))
        error ("lafortune:badScene", "%s: SCENE.camera.fov must be in (0, 180) degrees", fname);
      endif
      h = 2 * tand (fov / 2);
    otherwise
      error ("lafortune:badScene", "%s: unknown camera type '%s'", fname, c.type);
  endswitch
  cam = struct ("type", c.type, "eye", eye, "f", f, "r", r, "u", u,
                "w", h * W / H, "h", h, "W", W, "H", H);
endfunction
