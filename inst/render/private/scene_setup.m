## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{objs}, @var{epsilon}] =} scene_setup (@var{scene})
## The objects of a checked scene made ready for tracing (private, for
## @code{rt_render} and @code{merl_scene}): meshes get their BVH
## (@code{rt_bvh}), unit face normals @code{fn} and unit vertex normals,
## planes a unit normal.  @var{epsilon} is the offset of shadow rays, 1e-7
## times the size of the scene.
## @end deftypefn
function [objs, epsilon] = scene_setup (scene)
  objs = scene.objects;
  objs(1).bvh = [];
  objs(1).fn = [];
  scale = norm (scene.camera.eye - scene.camera.target);
  for k = 1:numel (objs)
    switch (objs(k).type)
      case "mesh"
        V = double (objs(k).vertices);
        F = double (objs(k).faces);
        objs(k).bvh = rt_bvh (V, F);
        fn = cross (V(F(:,2),:) - V(F(:,1),:), V(F(:,3),:) - V(F(:,1),:), 2);
        objs(k).fn = fn ./ max (sqrt (sum (fn .^ 2, 2)), realmin);
        if (! isempty (objs(k).normals))
          nv = double (objs(k).normals);
          objs(k).normals = nv ./ max (sqrt (sum (nv .^ 2, 2)), realmin);
        endif
        scale = max (scale, max (abs (V(:))));
      case "sphere"
        scale = max (scale, norm (objs(k).center) + objs(k).radius);
      case "plane"
        nrm = double (objs(k).normal(:).');
        objs(k).normal = nrm / norm (nrm);
    endswitch
  endfor
  epsilon = 1e-7 * scale;
endfunction
