## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{bvh} =} rt_bvh (@var{V}, @var{F})
## @deftypefnx {lafortune} {@var{bvh} =} rt_bvh (@var{V}, @var{F}, @var{leafsize})
## Build a bounding volume hierarchy over the triangles of a mesh.
##
## @var{V} (V x 3) and @var{F} (F x 3, 1-based) are the mesh.  The tree is a
## complete binary tree stored implicitly (heap order: node 1 is the root,
## the children of node k are 2k and 2k+1, the leaves are the 2^D nodes
## 2^D @dots{} 2^(D+1)-1).  It is built top-down, one level at a time and
## vectorised over all nodes of a level: every node splits its triangles at
## the median of their centroids along the node's longest centroid extent
## (one sort per level).  Leaves hold at most @var{leafsize} (default 4)
## triangles, on average between @var{leafsize}/2 and @var{leafsize}.
##
## Fields of @var{bvh}: @code{depth} (D), @code{nleaf} (2^D), @code{slots}
## (triangles per leaf, L), @code{bmin}, @code{bmax} (node boxes,
## (2^(D+1)-1) x 3; empty nodes have both corners at +Inf), @code{tri} (L*nleaf x 1
## triangle index per slot, 0 = empty; leaf j, 0-based, owns slots
## j*L+1 @dots{} j*L+L), @code{v0}, @code{e1}, @code{e2} (L*nleaf x 3: first
## vertex and edges of the slot's triangle, NaN for empty slots), the data
## @code{rt_intersect} traverses; and the same interleaved per node and per
## slot for its compiled traversal: @code{boxes} (6 x (2^(D+1)-1), column k
## = [bmin(k,:) bmax(k,:)]), @code{tris} (9 x L*nleaf, column s =
## [v0(s,:) e1(s,:) e2(s,:)]).
##
## @example
## @group
## [V, F] = mesh_torus ([224 224]);
## tic; bvh = rt_bvh (V, F); toc      # 100352 triangles
## bvh.depth
## @result{} 15
## @end group
## @end example
## @seealso{rt_intersect, rt_render, mesh_read}
## @end deftypefn

function bvh = rt_bvh (V, F, leafsize)
  if (nargin < 2 || nargin > 3)
    print_usage ();
  endif
  if (nargin < 3)
    leafsize = 4;
  endif
  if (! (isnumeric (V) && isreal (V) && ismatrix (V) && columns (V) == 3
         && all (isfinite (V(:)))))
    error ("lafortune:badMesh", "rt_bvh: V must be a finite V x 3 array of vertices");
  endif
  if (! (isnumeric (F) && ismatrix (F) && columns (F) == 3 && rows (F) >= 1
         && all (F(:) == fix (F(:))) && all (F(:) >= 1) && all (F(:) <= rows (V))))
    error ("lafortune:badMesh",
           "rt_bvh: F must be an F x 3 array of 1-based vertex indices (1 to %d), at least one row",
           rows (V));
  endif
  if (! (isscalar (leafsize) && leafsize >= 1 && leafsize == fix (leafsize)))
    error ("lafortune:badOption", "rt_bvh: LEAFSIZE must be a positive integer");
  endif
  V = double (V);
  F = double (F);
  nf = rows (F);
  A = V(F(:,1),:);
  B = V(F(:,2),:);
  C = V(F(:,3),:);
  cen = (A + B + C) / 3;
  D = max (0, ceil (log2 (nf / leafsize)));
  nleaf = 2 ^ D;

  ## top-down median splits, one level at a time
  order = (1:nf).';
  p = (0:nf-1).';
  for d = 0:D-1
    nn = 2 ^ d;
    starts = floor ((0:nn-1).' * nf / nn);
    node = lookup (starts, p);              # 1-based node of each position
    c = cen(order,:);
    lo = zeros (nn, 3);
    hi = zeros (nn, 3);
    for k = 1:3
      lo(:,k) = accumarray (node, c(:,k), [nn 1], @min);
      hi(:,k) = accumarray (node, c(:,k), [nn 1], @max);
    endfor
    [ext, ax] = max (hi - lo, [], 2);
    idx = sub2ind ([nf 3], (1:nf).', ax(node));
    frac = (c(idx) - lo(:)(sub2ind ([nn 3], node, ax(node)))) ./ (ext(node) * (1 + 1e-9) + realmin);
    [~, o] = sort (node + frac);
    order = order(o);
  endfor

  ## leaves: slot layout and boxes
  lstart = floor ((0:nleaf-1).' * nf / nleaf);
  leaf = lookup (lstart, p);               # 1-based leaf of each position
  L = max (diff ([lstart; nf]));
  slot = (leaf - 1) * L + (p - lstart(leaf)) + 1;
  tri = zeros (L * nleaf, 1);
  tri(slot) = order;
  nnode = 2 * nleaf - 1;
  bmin = Inf (nnode, 3);
  bmax = -Inf (nnode, 3);
  tmin = min (min (A(order,:), B(order,:)), C(order,:));
  tmax = max (max (A(order,:), B(order,:)), C(order,:));
  full = accumarray (leaf, 1, [nleaf 1]) > 0;
  for k = 1:3
    lo = accumarray (leaf, tmin(:,k), [nleaf 1], @min);
    hi = accumarray (leaf, tmax(:,k), [nleaf 1], @max);
    bmin(nleaf - 1 + find (full),k) = lo(full);
    bmax(nleaf - 1 + find (full),k) = hi(full);
  endfor
  for d = D-1:-1:0
    i = (2^d:2^(d+1)-1).';
    bmin(i,:) = min (bmin(2*i,:), bmin(2*i+1,:));
    bmax(i,:) = max (bmax(2*i,:), bmax(2*i+1,:));
  endfor
  ## empty nodes: a box at +Inf, which the slab test never hits
  empty = any (bmin > bmax, 2);
  bmin(empty,:) = Inf;
  bmax(empty,:) = Inf;

  v0 = NaN (L * nleaf, 3);
  e1 = v0;
  e2 = v0;
  v0(slot,:) = A(order,:);
  e1(slot,:) = B(order,:) - A(order,:);
  e2(slot,:) = C(order,:) - A(order,:);
  bvh = struct ("depth", D, "nleaf", nleaf, "slots", L, "bmin", bmin, "bmax", bmax,
                "tri", tri, "v0", v0, "e1", e1, "e2", e2,
                "boxes", [bmin bmax].', "tris", [v0 e1 e2].');
endfunction

%!test
%! [V, F] = mesh_torus ([24 12]);
%! b = rt_bvh (V, F);
%! assert (b.nleaf, 2 ^ b.depth);
%! assert (b.slots <= 4);
%! ## every triangle in exactly one slot
%! t = b.tri(b.tri > 0);
%! assert (sort (t), (1:rows (F))');
%! ## every node box holds its children's boxes, every leaf box its triangles
%! n = (1:b.nleaf-1)';
%! for c = [2*n, 2*n+1]
%!   assert (all (all (b.bmin(n,:) <= b.bmin(c,:) & b.bmax(n,:) >= b.bmax(c,:))));
%! endfor
%! s = find (b.tri > 0);
%! leaf = b.nleaf + floor ((s - 1) / b.slots);
%! T = F(b.tri(s),:);
%! for k = 1:3
%!   P = V(T(:,k),:);
%!   assert (all (all (P >= b.bmin(leaf,:) & P <= b.bmax(leaf,:))));
%! endfor
%! assert (b.v0(s,:), V(T(:,1),:));
%! assert (b.e2(s,:), V(T(:,3),:) - V(T(:,1),:));
%! ## the interleaved copies
%! assert (b.boxes, [b.bmin b.bmax].');
%! assert (b.tris(:,s), [b.v0(s,:) b.e1(s,:) b.e2(s,:)].');
%! ## the splits localise: a leaf box is hardly larger than its triangles
%! dl = mean (sqrt (sum ((b.bmax(b.nleaf:end,:) - b.bmin(b.nleaf:end,:)) .^ 2, 2)));
%! A = V(F(:,1),:); B = V(F(:,2),:); C = V(F(:,3),:);
%! dt = mean (sqrt (sum ((max (max (A, B), C) - min (min (A, B), C)) .^ 2, 2)));
%! assert (dl < 2 * dt);

%!test
%! ## a single triangle, a leaf size of 1
%! b = rt_bvh ([0 0 0; 1 0 0; 0 1 0], [1 2 3]);
%! assert ([b.depth b.nleaf b.slots b.tri], [0 1 1 1]);
%! assert ([b.bmin; b.bmax], [0 0 0; 1 1 0]);
%! b = rt_bvh ([0 0 0; 1 0 0; 0 1 0; 1 1 0], [1 2 3; 2 4 3; 1 2 4], 1);
%! assert ([b.depth b.nleaf b.slots], [2 4 1]);
%! assert (sort (b.tri), [0; 1; 2; 3]);
%! assert (b.bmin(b.nleaf - 1 + find (b.tri == 0),:), Inf (1, 3));

%!error <Invalid call> rt_bvh (1)
%!error id=lafortune:badMesh rt_bvh ([0 0 0], [1 1 2])
%!error id=lafortune:badMesh rt_bvh ([0 0; 1 1; 2 2], [1 2 3])
%!error id=lafortune:badMesh rt_bvh (zeros (3, 3), zeros (0, 3))
