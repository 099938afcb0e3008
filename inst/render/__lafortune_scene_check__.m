## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {} __lafortune_scene_check__ (@var{scene}, @var{fname})
## @deftypefnx {} {} __lafortune_scene_check__ (@var{scene}, @var{fname}, "view")
## The one check of a scene struct (private, for @code{rt_render},
## @code{scene_slice}, @code{pov_write_scene} and the camera helpers): every
## field that a renderer reads, with its shape.  With @qcode{"view"} only
## the camera and the light (what @code{scene_slice} reads).  Errors
## @code{lafortune:badScene}, naming @var{fname} and the field.
## @end deftypefn
function __lafortune_scene_check__ (scene, fname, part = "all")
  if (strcmp (part, "view"))
    need = {"camera", "light"};
  else
    need = {"width", "height", "spp", "seed", "background", "camera", "light", "objects"};
  endif
  if (! isstruct (scene) || ! isscalar (scene) || ! all (isfield (scene, need)))
    error ("lafortune:badScene", "%s: SCENE must be a scene struct from scene_make (fields %s)",
           fname, strjoin (need, ", "));
  endif
  if (strcmp (part, "view"))
    check_camera (scene.camera, fname);
    check_light (scene.light, fname);
    return;
  endif
  W = scene.width;
  H = scene.height;
  if (! posint (W) || ! posint (H))
    error ("lafortune:badScene", "%s: SCENE.width and SCENE.height must be positive integers",
           fname);
  endif
  if (! posint (scene.spp))
    error ("lafortune:badScene", "%s: SCENE.spp must be a positive integer", fname);
  endif
  if (! (isnumeric (scene.seed) && isscalar (scene.seed) && isfinite (scene.seed)))
    error ("lafortune:badScene", "%s: SCENE.seed must be a finite number", fname);
  endif
  if (! vec3 (scene.background))
    error ("lafortune:badScene", "%s: SCENE.background must be a finite 1 x 3 radiance", fname);
  endif
  if (isfield (scene, "jitter") && ! (isscalar (scene.jitter)
                                      && (islogical (scene.jitter) || isnumeric (scene.jitter))))
    error ("lafortune:badScene", "%s: SCENE.jitter must be true or false", fname);
  endif
  check_camera (scene.camera, fname);
  check_light (scene.light, fname);
  check_objects (scene.objects, fname);
endfunction

function check_camera (c, fname)
  if (! isstruct (c) || ! isscalar (c) || ! all (isfield (c, {"type", "eye", "target", "up"})))
    error ("lafortune:badScene", "%s: SCENE.camera needs the fields type, eye, target, up",
           fname);
  endif
  if (! vec3 (c.eye) || ! vec3 (c.target) || ! vec3 (c.up)
      || ! (norm (double (c.target(:)) - double (c.eye(:))) > 0))
    error ("lafortune:badScene",
           "%s: SCENE.camera.eye, .target and .up must be finite 3-vectors, eye and target distinct",
           fname);
  endif
  f = double (c.target(:)' - c.eye(:)');
  if (! (norm (cross (f / norm (f), double (c.up(:)'))) > 1e-12))
    error ("lafortune:badScene", "%s: SCENE.camera.up must not be parallel to the view direction",
           fname);
  endif
  switch (c.type)
    case "orthographic"
      if (! isfield (c, "extent") || ! (isnumeric (c.extent) && isscalar (c.extent)
                                        && c.extent > 0 && isfinite (c.extent)))
        error ("lafortune:badScene", "%s: SCENE.camera.extent must be a positive scalar", fname);
      endif
    case "perspective"
      if (! isfield (c, "fov") || ! (isnumeric (c.fov) && isscalar (c.fov)
                                     && c.fov > 0 && c.fov < 180))
        error ("lafortune:badScene", "%s: SCENE.camera.fov must be in (0, 180) degrees", fname);
      endif
    otherwise
      error ("lafortune:badScene",
             "%s: unknown camera type '%s' (expected orthographic or perspective)", fname,
             __lafortune_arg_str__ (c.type));
  endswitch
endfunction

function check_light (lt, fname)
  if (! isstruct (lt) || ! isscalar (lt) || ! all (isfield (lt, {"type", "irradiance"})))
    error ("lafortune:badScene", "%s: SCENE.light needs the fields type and irradiance", fname);
  endif
  E = lt.irradiance;
  if (strcmp (lt.type, "lights"))
    if (! isfield (lt, "directions") || ! (isnumeric (lt.directions) && isreal (lt.directions)
                                          && ndims (lt.directions) == 2
                                          && columns (lt.directions) == 3
                                          && rows (lt.directions) >= 1
                                          && all (isfinite (lt.directions(:)))
                                          && all (sum (lt.directions .^ 2, 2) > 0)))
      error ("lafortune:badScene",
             "%s: SCENE.light.directions must be a K x 3 array of finite non-zero directions",
             fname);
    endif
    if (! (isnumeric (E) && isreal (E) && isequal (size (E), [rows(lt.directions) 3])
           && all (isfinite (E(:))) && all (E(:) >= 0)))
      error ("lafortune:badScene",
             "%s: SCENE.light.irradiance of %d lights must be %d x 3, finite, >= 0", fname,
             rows (lt.directions), rows (lt.directions));
    endif
    return;
  endif
  if (! (isnumeric (E) && isreal (E) && any (numel (E) == [1 3]) && all (isfinite (E(:)))
         && all (E(:) >= 0)))
    error ("lafortune:badScene", "%s: SCENE.light.irradiance must be a scalar or 1 x 3, >= 0",
           fname);
  endif
  switch (lt.type)
    case "environment"
      need = {"map", "rotation", "samples"};
      if (! all (isfield (lt, need)))
        error ("lafortune:badScene", "%s: SCENE.light (environment) needs the fields %s",
               fname, strjoin (need, ", "));
      endif
      M = lt.map;
      if (! (isnumeric (M) && isreal (M) && ndims (M) == 3 && size (M, 3) == 3
             && columns (M) == 2 * rows (M) && rows (M) >= 4 && all (isfinite (M(:)))
             && all (M(:) >= 0) && any (M(:) > 0)))
        error ("lafortune:badScene",
               "%s: SCENE.light.map must be an H x 2H x 3 radiance array, finite, >= 0, not all 0",
               fname);
      endif
      if (! (isnumeric (lt.rotation) && isscalar (lt.rotation) && isfinite (lt.rotation)))
        error ("lafortune:badScene", "%s: SCENE.light.rotation must be a finite angle", fname);
      endif
      if (! posint (lt.samples))
        error ("lafortune:badScene", "%s: SCENE.light.samples must be a positive integer",
               fname);
      endif
    case "directional"
      if (! isfield (lt, "direction") || ! vec3 (lt.direction) || ! (norm (lt.direction) > 0))
        error ("lafortune:badScene", "%s: SCENE.light.direction must be a nonzero 3-vector",
               fname);
      endif
    case "point"
      if (! isfield (lt, "position") || ! vec3 (lt.position))
        error ("lafortune:badScene", "%s: SCENE.light.position must be a finite 3-vector", fname);
      endif
    otherwise
      error ("lafortune:badScene",
             "%s: unknown light type '%s' (expected directional, point, environment or lights)", fname,
             __lafortune_arg_str__ (lt.type));
  endswitch
endfunction

function check_objects (ob, fname)
  if (! isstruct (ob) || ! isfield (ob, "type"))
    error ("lafortune:badScene", "%s: SCENE.objects must be a struct array with a field type",
           fname);
  endif
  if (isempty (ob))
    error ("lafortune:badScene", "%s: the scene has no objects", fname);
  endif
  for k = 1:numel (ob)
    o = ob(k);
    switch (o.type)
      case "sphere"
        ok = vec3 (o.center) && isnumeric (o.radius) && isscalar (o.radius) && o.radius > 0 ...
             && isfinite (o.radius);
      case "plane"
        ok = vec3 (o.point) && vec3 (o.normal) && norm (o.normal) > 0;
      case "mesh"
        V = o.vertices;
        F = o.faces;
        ok = (isnumeric (V) && columns (V) == 3 && all (isfinite (V(:)))
              && isnumeric (F) && columns (F) == 3 && ! isempty (F)
              && all (F(:) >= 1) && all (F(:) <= rows (V)) && all (F(:) == fix (F(:)))
              && (isempty (o.normals) || isequal (size (o.normals), size (V))));
      otherwise
        error ("lafortune:badScene",
               "%s: unknown object type '%s' (expected sphere, plane or mesh)", fname,
               __lafortune_arg_str__ (o.type));
    endswitch
    if (! ok)
      error ("lafortune:badScene", "%s: SCENE.objects(%d) is not a valid %s", fname, k, o.type);
    endif
  endfor
endfunction

function tf = posint (v)
  tf = isnumeric (v) && isscalar (v) && isreal (v) && v >= 1 && v == fix (v) && isfinite (v);
endfunction

function tf = vec3 (v)
  tf = isnumeric (v) && isreal (v) && numel (v) == 3 && all (isfinite (v(:)));
endfunction
