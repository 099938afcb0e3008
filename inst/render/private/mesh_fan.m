## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{F} =} mesh_fan (@var{idx}, @var{ncorner})
## Fan-triangulate polygons (private, for mesh_read).  @var{idx} holds the
## corner indices of all polygons one after the other, @var{ncorner} (one
## entry per polygon, each >= 3) their corner counts.  The polygon
## v1 v2 @dots{} vn gives the triangles (v1, vk, vk+1), k = 2 @dots{} n-1;
## @var{F} (T x 3) lists them in file order: polygon, then fan.  Indices are
## copied as they are (no range check).
## @end deftypefn
function F = mesh_fan (idx, ncorner)
  idx = idx(:);
  ncorner = ncorner(:);
  cstart = cumsum ([1; ncorner(1:end-1)]);
  F = zeros (0, 3);
  key = zeros (0, 1);
  for m = unique (ncorner).'
    id = find (ncorner == m);
    P = reshape (idx(cstart(id) + (0:m-1)), numel (id), m);   # polygons x m
    k = 2:m-1;
    F = [F; repmat(P(:,1), 1, m-2)(:), P(:,k)(:), P(:,k+1)(:)];
    key = [key; (id + (k - 1) / m)(:)];
  endfor
  [~, o] = sort (key);
  F = F(o,:);
endfunction
