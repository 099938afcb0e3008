## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {[@var{V}, @var{F}, @var{N}] =} mesh_torus ()
## @deftypefnx {lafortune} {[@var{V}, @var{F}, @var{N}] =} mesh_torus (@var{res})
## @deftypefnx {lafortune} {[@var{V}, @var{F}, @var{N}] =} mesh_torus (@var{res}, @var{R}, @var{r})
## Tessellated torus with exact vertex normals, the toolbox's built-in mesh.
##
## The torus lies around the y axis: the centre line is the circle of radius
## @var{R} (default 1) in the x-z plane, the tube radius is @var{r} (default
## 0.4).  @var{res} = [@var{nu} @var{nv}] (default [96 48]) is the number of
## segments around the centre line and around the tube; the mesh has
## @var{nu}*@var{nv} vertices and 2*@var{nu}*@var{nv} triangles, wound
## counter-clockwise seen from outside (cross (B - A, C - A) points out).
## A scalar @var{res} means [@var{res} ceil(@var{res}/2)].
##
## @var{V} and @var{N} are V x 3 (positions, unit normals), @var{F} is F x 3
## (1-based indices), the layout of @code{mesh_read} and of the scene
## objects of type "mesh".
##
## @example
## @group
## [V, F, N] = mesh_torus ([224 224]);   # 100352 triangles
## size (F)
## @result{} 100352 3
## @end group
## @end example
## @seealso{scene_make, mesh_read}
## @end deftypefn

function [V, F, N] = mesh_torus (res, R, r)
  if (nargin > 3)
    print_usage ();
  endif
  if (nargin < 1 || isempty (res))
    res = [96 48];
  endif
  if (nargin < 2)
    R = 1;
  endif
  if (nargin < 3)
    r = 0.4;
  endif
  if (! isnumeric (res) || ! any (numel (res) == [1 2]) || any (res != fix (res))
      || any (res < 3))
    error ("lafortune:badOption",
           "mesh_torus: RES must be [NU NV] (or a scalar) of integers >= 3, got %s",
           mat2str (res));
  endif
  if (isscalar (res))
    res = [res, max(3, ceil(res / 2))];
  endif
  if (! (isscalar (R) && isscalar (r) && isreal (R) && isreal (r) && r > 0 && R > r))
    error ("lafortune:badOption",
           "mesh_torus: radii must be scalars with R > r > 0, got R = %g, r = %g", R, r);
  endif
  nu = double (res(1));
  nv = double (res(2));
  u = 2 * pi * (0:nu-1) / nu;              # around the centre line
  v = 2 * pi * (0:nv-1).' / nv;            # around the tube
  [U, W] = meshgrid (u, v);                # nv x nu, vertex (j, i) -> j + (i-1)*nv
  N = [cos(W)(:) .* cos(U)(:), sin(W)(:), cos(W)(:) .* sin(U)(:)];
  V = R * [cos(U)(:), zeros(nu*nv, 1), sin(U)(:)] + r * N;
  [J, I] = ndgrid (0:nv-1, 0:nu-1);
  a = J + I * nv + 1;
  b = J + mod (I + 1, nu) * nv + 1;
  c = mod (J + 1, nv) + mod (I + 1, nu) * nv + 1;
  d = mod (J + 1, nv) + I * nv + 1;
  F = [a(:) b(:) c(:); a(:) c(:) d(:)];
  ## wind outward: compare the face normal with the vertex normals
  n1 = cross (V(F(1,2),:) - V(F(1,1),:), V(F(1,3),:) - V(F(1,1),:));
  if (dot (n1, N(F(1,1),:)) < 0)
    F = F(:, [1 3 2]);
  endif
endfunction

%!test
%! [V, F, N] = mesh_torus ([12 8], 2, 0.5);
%! assert (size (V), [96 3]);
%! assert (size (F), [192 3]);
%! assert (sqrt (sum (N .^ 2, 2)), ones (96, 1), 1e-12);
%! ## every vertex on the torus surface
%! rho = sqrt (V(:,1) .^ 2 + V(:,3) .^ 2);
%! assert ((rho - 2) .^ 2 + V(:,2) .^ 2, 0.25 * ones (96, 1), 1e-12);
%! ## faces wound outward and every edge shared by exactly two faces
%! fn = cross (V(F(:,2),:) - V(F(:,1),:), V(F(:,3),:) - V(F(:,1),:));
%! assert (all (sum (fn .* (N(F(:,1),:) + N(F(:,2),:) + N(F(:,3),:)), 2) > 0));
%! E = sort ([F(:,[1 2]); F(:,[2 3]); F(:,[3 1])], 2);
%! [~, ~, j] = unique (E, "rows");
%! assert (all (accumarray (j, 1) == 2));
%! ## closed surface: enclosed volume close to 2 pi^2 R r^2
%! [V, F] = mesh_torus ([96 48], 2, 0.5);
%! vol = sum (dot (V(F(:,1),:), cross (V(F(:,2),:), V(F(:,3),:)), 2)) / 6;
%! assert (vol, 2 * pi ^ 2 * 2 * 0.25, 0.01 * vol);

%!test
%! [V, F] = mesh_torus (10);
%! assert (size (F), [100 3]);

%!error <called with too many inputs> mesh_torus (1, 2, 3, 4)
%!error id=lafortune:badOption mesh_torus ([2 8])
%!error id=lafortune:badOption mesh_torus ([8 8], 1, 2)
