## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{Ng}, @var{Ns}] =} __lafortune_hit_normals__ (@var{objs}, @var{hit}, @var{h}, @var{P})
## Geometric and shading normals (unit, as the surface defines them, not yet
## turned toward the viewer) at the hits @var{h} (indices into the
## @code{rt_intersect} result @var{hit}) at the points @var{P} (private, for
## @code{rt_render} and @code{pov_cast}).  Mesh objects need the field
## @code{fn} (unit face normals) and, when they have vertex normals, unit
## @code{normals}: the shading normal is then interpolated with the hit's
## barycentric coordinates, else it is the face normal.
## @end deftypefn
function [Ng, Ns] = __lafortune_hit_normals__ (objs, hit, h, P)
  Ng = zeros (numel (h), 3);
  Ns = Ng;
  ob = hit.obj(h);
  for k = unique (ob).'
    s = ob == k;
    o = objs(k);
    switch (o.type)
      case "sphere"
        Ng(s,:) = (P(s,:) - o.center(:).') / o.radius;
        Ng(s,:) ./= sqrt (sum (Ng(s,:) .^ 2, 2));
        Ns(s,:) = Ng(s,:);
      case "plane"
        Ng(s,:) = repmat (o.normal(:).' / norm (o.normal), nnz (s), 1);
        Ns(s,:) = Ng(s,:);
      case "mesh"
        tri = hit.prim(h(s));
        Ng(s,:) = o.fn(tri,:);
        if (isempty (o.normals))
          Ns(s,:) = Ng(s,:);
        else
          u = hit.u(h(s));
          v = hit.v(h(s));
          F = o.faces(tri,:);
          n = (1 - u - v) .* o.normals(F(:,1),:) + u .* o.normals(F(:,2),:) ...
              + v .* o.normals(F(:,3),:);
          len = sqrt (sum (n .^ 2, 2));
          ok = len > 1e-12;
          n(ok,:) ./= len(ok);
          n(! ok,:) = Ng(s,:)(! ok,:);
          Ns(s,:) = n;
        endif
    endswitch
  endfor
endfunction
