## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {[@var{S}, @var{G}] =} pov_cast (@var{scene}, @var{cam}, @var{L})
## @deftypefnx {} {[@var{S}, @var{G}] =} pov_cast (@var{scene}, @var{cam}, @var{L}, @var{G})
## What the view of @var{scene} reaches (private, for @code{pov_write_scene}).
##
## Rays are cast on a half-pixel grid ((2W+1) x (2H+1) rays: the pixel centres,
## corners and edge midpoints) against the spheres and planes; mesh vertices
## (and face centroids) inside the view stand in for the meshes.  Normals are
## turned toward the viewer, as POV-Ray does.  Mesh occlusion is ignored, so
## the samples are a superset of what is seen.  @var{L} is the unit direction
## toward a directional light, or empty for the point light
## @code{scene.light.position}.
##
## Fields of @var{S}: @code{ti}, @code{to}, @code{gamma} (angles between the
## normal and the light, the normal and the viewer, the light and the viewer)
## and @code{P} (points) of the samples that face the light (ti < pi/2);
## @code{keep} (1 x numel (scene.objects) logical): the object is in the view
## or may cast a shadow on a sample; @code{faces}: cell with, for meshes, the
## F x 1 logical mask of faces in the view or possibly shadowing a sample
## (conservative bounding-box tests).
##
## @var{G} is what does not depend on the light (the samples' points,
## normals toward the viewer, view directions, the objects and faces in
## the view): pass it back for another light of the same view, and the
## rays are not cast again.  Without @var{G}, the geometry of the last
## view cast in this Octave session is used again when @var{scene} and
## @var{cam} are the same (every fit of a material rendered in one process
## casts the view once).
## @end deftypefn
function [S, G] = pov_cast (scene, cam, L, G = [])
  persistent last;
  ob = scene.objects;
  nob = numel (ob);
  if (isempty (G))
    if (! isempty (last) && isequal (last.cam, cam) && isequal (last.scene, scene))
      G = last.G;
    else
      G = cast_view (scene, cam);
      last = struct ("scene", scene, "cam", cam, "G", G);
    endif
  endif
  P = G.P;
  N = G.N;
  V = G.V;
  keep = G.keep;
  faces = G.faces;
  if (isempty (L))
    Lp = double (scene.light.position(:)') - P;
    Lp ./= sqrt (sum (Lp .^ 2, 2));
  else
    Lp = repmat (L, rows (P), 1);
  endif
  cl = sum (N .* Lp, 2);
  lit = cl > 0;
  S.P = P(lit,:);
  S.ti = acos (min (cl(lit), 1));
  S.to = acos (min (max (sum (N(lit,:) .* V(lit,:), 2), -1), 1));
  S.gamma = acos (min (max (sum (Lp(lit,:) .* V(lit,:), 2), -1), 1));
  ## what may cast a shadow on a sample
  for k = 1:nob
    switch (ob(k).type)
      case "sphere"
        if (! keep(k))
          keep(k) = shadows_sphere (S.P, L, scene.light, double (ob(k).center(:)'),
                                    double (ob(k).radius));
        endif
      case "plane"
        keep(k) = true;
      case "mesh"
        sh = shadows_faces (S.P, L, double (ob(k).vertices), double (ob(k).faces));
        faces{k} |= sh;
        keep(k) = any (faces{k});
    endswitch
  endfor
  S.keep = keep;
  S.faces = faces;
endfunction

## the samples of the view: points, normals toward the viewer, view
## directions, and the objects and mesh faces in the view
function G = cast_view (scene, cam)
  ob = scene.objects;
  nob = numel (ob);
  ## rays on the half-pixel grid, against the spheres and planes
  [X, Y] = meshgrid ((0:2*cam.W) / (2*cam.W) - 0.5, 0.5 - (0:2*cam.H) / (2*cam.H));
  [O, D] = __lafortune_camera_rays__ (cam, X, Y);
  t = inf (rows (O), 1);
  hitobj = zeros (rows (O), 1);
  analytic = find (! strcmp ({ob.type}, "mesh"));
  if (! isempty (analytic))
    hc = rt_intersect (ob(analytic), O, D);
    t = hc.t;
    hitobj(hc.obj > 0) = analytic(hc.obj(hc.obj > 0));
  endif
  hit = isfinite (t);
  P = O(hit,:) + t(hit) .* D(hit,:);
  N = zeros (0, 3);
  if (any (hit))
    N = __lafortune_hit_normals__ (ob(analytic), hc, find (hit), P);
  endif
  V = -D(hit,:);
  keep = false (1, nob);
  keep(unique (hitobj(hit))) = true;
  ## meshes: faces in the view, their vertices as samples
  faces = cell (1, nob);
  for k = 1:nob
    if (strcmp (ob(k).type, "mesh"))
      vx = double (ob(k).vertices);
      fc = double (ob(k).faces);
      faces{k} = in_view (cam, vx, fc);
      keep(k) = any (faces{k});
      [Pm, Nm] = mesh_samples (vx, fc(faces{k},:), ob(k).normals);
      if (strcmp (cam.type, "orthographic"))
        Vm = repmat (-cam.f, rows (Pm), 1);
      else
        Vm = cam.eye - Pm;
        Vm ./= sqrt (sum (Vm .^ 2, 2));
      endif
      P = [P; Pm];
      N = [N; Nm];
      V = [V; Vm];
    endif
  endfor
  N .*= sign (sum (N .* V, 2) + (sum (N .* V, 2) == 0));     # toward the viewer
  G = struct ("P", P, "N", N, "V", V, "keep", keep, "faces", {faces});
endfunction

## faces whose projected bounding box overlaps the view (one pixel margin)
function inv = in_view (cam, vx, fc)
  d = vx - cam.eye;
  z = d * cam.f';
  x = d * cam.r';
  y = d * cam.u';
  mx = cam.w / cam.W;
  my = cam.h / cam.H;
  if (strcmp (cam.type, "perspective"))
    zz = max (z, 1e-9);
    x ./= zz;
    y ./= zz;
  endif
  F = fc;
  zmax = max (z(F), [], 2);
  zmin = min (z(F), [], 2);
  xl = min (x(F), [], 2); xh = max (x(F), [], 2);
  yl = min (y(F), [], 2); yh = max (y(F), [], 2);
  inv = zmax > 0 & xh >= -cam.w/2 - mx & xl <= cam.w/2 + mx ...
        & yh >= -cam.h/2 - my & yl <= cam.h/2 + my;
  if (strcmp (cam.type, "perspective"))
    inv |= zmax > 0 & zmin <= 1e-9;            # crosses the eye plane: keep
  endif
endfunction

function [P, N] = mesh_samples (vx, fc, nv)
  if (isempty (fc))
    P = zeros (0, 3);
    N = zeros (0, 3);
    return;
  endif
  fn = cross (vx(fc(:,2),:) - vx(fc(:,1),:), vx(fc(:,3),:) - vx(fc(:,1),:), 2);
  fn ./= max (sqrt (sum (fn .^ 2, 2)), realmin);
  if (isempty (nv))
    P = [(vx(fc(:,1),:) + vx(fc(:,2),:) + vx(fc(:,3),:)) / 3; vx(fc(:),:)];
    N = repmat (fn, 4, 1);
  else
    nv = double (nv);
    nv ./= max (sqrt (sum (nv .^ 2, 2)), realmin);
    P = vx(fc(:),:);
    N = nv(fc(:),:);
  endif
endfunction

function s = shadows_sphere (P, L, light, c, rad)
  if (isempty (P))
    s = false;
    return;
  endif
  if (isempty (L))
    dl = double (light.position(:)') - P;
    len = sqrt (sum (dl .^ 2, 2));
    dl ./= len;
  else
    dl = repmat (L, rows (P), 1);
    len = inf (rows (P), 1);
  endif
  cp = c - P;
  tc = sum (cp .* dl, 2);
  tq = min (max (tc, 0), len);
  d2 = sum ((cp - tq .* dl) .^ 2, 2);
  s = any (d2 <= rad ^ 2 * (1 + 1e-6));
endfunction

## faces whose bounding box, seen along the light, covers a sample; with a
## point light every face is kept
function sh = shadows_faces (P, L, vx, fc)
  nf = rows (fc);
  if (isempty (P))
    sh = false (nf, 1);
    return;
  elseif (isempty (L))
    sh = true (nf, 1);
    return;
  endif
  a = null (L)';                               # 2 x 3, orthonormal, both _|_ L
  ps = P * a';
  vs = vx * a';
  lo = min (ps, [], 1);
  hi = max (ps, [], 1);
  ng = 64;
  cell_ = max ((hi - lo) / ng, 1e-9);
  ij = min (floor ((ps - lo) ./ cell_), ng - 1) + 1;
  occ = accumarray (ij, 1, [ng ng]) > 0;
  C = zeros (ng + 1);
  C(2:end,2:end) = cumsum (cumsum (occ, 1), 2);
  X1 = reshape (vs(fc(:),1), nf, 3);
  X2 = reshape (vs(fc(:),2), nf, 3);
  fl = [min(X1, [], 2), min(X2, [], 2)];
  fh = [max(X1, [], 2), max(X2, [], 2)];
  i0 = floor ((fl - lo) ./ cell_) + 1;
  i1 = floor ((fh - lo) ./ cell_) + 1;
  out = any (i1 < 1, 2) | any (i0 > ng, 2);
  i0 = min (max (i0, 1), ng);
  i1 = min (max (i1, 1), ng);
  cnt = C(sub2ind ([ng+1 ng+1], i1(:,1) + 1, i1(:,2) + 1)) ...
        - C(sub2ind ([ng+1 ng+1], i0(:,1), i1(:,2) + 1)) ...
        - C(sub2ind ([ng+1 ng+1], i1(:,1) + 1, i0(:,2))) ...
        + C(sub2ind ([ng+1 ng+1], i0(:,1), i0(:,2)));
  sh = ! out & cnt > 0;
endfunction
