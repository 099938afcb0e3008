## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{V}, @var{F}, @var{N}, @var{info}] =} mesh_finish (@var{V}, @var{F}, @var{N}, @var{info}, @var{file})
## The checks and clean-up common to every mesh format (private, for
## mesh_read): at least one vertex, finite coordinates and normals; degenerate
## triangles dropped (a repeated index, or zero area: |AB x AC| <= 4 eps |AB|
## |AC|, i.e. collinear or coincident corners up to rounding), at least one
## triangle left; unit normals, a zero-length normal replaced by the
## area-weighted mean of the normals of the triangles around the vertex.
## Sets @var{info}.vertices, .faces, .triangles, .degenerate and .filled.
## @end deftypefn
function [V, F, N, info] = mesh_finish (V, F, N, info, file)
  if (isempty (V))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no vertices", file);
  endif
  if (isempty (F))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no faces", file);
  endif
  if (! all (isfinite (V(:))))
    i = find (! all (isfinite (V), 2), 1);
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: vertex %d has non-finite coordinates (%g %g %g); expected finite numbers",
           file, i, V(i,:));
  endif
  if (! isempty (N) && ! all (isfinite (N(:))))
    i = find (! all (isfinite (N), 2), 1);
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: the normal of vertex %d is not finite (%g %g %g); expected finite numbers",
           file, i, N(i,:));
  endif

  ## degenerate triangles
  info.triangles = rows (F);
  e1 = V(F(:,2),:) - V(F(:,1),:);
  e2 = V(F(:,3),:) - V(F(:,1),:);
  c = cross (e1, e2, 2);
  area2 = sqrt (sum (c .^ 2, 2));
  flat = area2 <= 4 * eps * sqrt (sum (e1 .^ 2, 2) .* sum (e2 .^ 2, 2));
  rep = F(:,1) == F(:,2) | F(:,2) == F(:,3) | F(:,1) == F(:,3);
  drop = flat | rep;
  info.degenerate = nnz (drop);
  if (all (drop))
    error ("lafortune:meshReadCount",
           "mesh_read: %s: all %d triangles are degenerate (repeated corners or zero area); expected at least one with an area",
           file, rows (F));
  endif
  F = F(! drop,:);
  c = c(! drop,:);

  ## unit normals; zero-length ones from the triangles around the vertex
  info.filled = 0;
  if (! isempty (N))
    len = sqrt (sum (N .^ 2, 2));
    zero = len == 0;
    N(! zero,:) ./= len(! zero);
    if (any (zero))
      acc = zeros (rows (V), 3);
      for k = 1:3
        acc(:,k) = accumarray (F(:), repmat (c(:,k), 3, 1), [rows(V) 1]);
      endfor
      la = sqrt (sum (acc .^ 2, 2));
      got = zero & la > 0;
      N(got,:) = acc(got,:) ./ la(got);
      info.filled = nnz (got);
    endif
  endif
  info.vertices = rows (V);
  info.faces = rows (F);
endfunction
