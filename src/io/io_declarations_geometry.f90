!> The declarations of the geometry groups (&geometry, &centerline,
!> &slide_elements, &cross_section, &blended, &bspline): each variable once
!> (io_declaration). A name two groups share with different meanings or
!> ranges (&centerline radius, &cross_section radius) is declared for each.
!> The largest counts are named here, so that the reader's array sizes and
!> the declared ranges are one number.
module io_declarations_geometry
  use base_kinds, only: wp
  use io_declaration, only: declaration_t, VALUE_REAL, VALUE_INTEGER, VALUE_LOGICAL, VALUE_WORDS
  implicit none (type, external)
  private
  public :: geometry_declarations
  public :: max_centerline_points, max_sections, max_elements, max_patches, max_profile_points

  integer, parameter :: max_centerline_points = 2000, max_sections = 8, max_elements = 40, max_patches = 8
  integer, parameter :: max_profile_points = 400

  type(declaration_t), parameter :: geometry_declarations(*) = [ &
    ! ---- &geometry
    declaration_t(groups='geometry', name='kind', kind=VALUE_WORDS, default='''slide''', &
      choices='tube slide blended bspline', meaning='which surface: a tube on `&centerline`, a tube on '// &
      '`&slide_elements`, `&blended`, `&bspline` (with `&cross_section` for a tube or slide)'), &
    declaration_t(groups='geometry', name='check_samples', kind=VALUE_INTEGER, unit='1', default='2000', &
      low=10.0_wp, high=1e6_wp, meaning='points along u at which a tube is checked (frame, folding)'), &
    ! ---- &centerline (kind = 'tube')
    declaration_t(groups='centerline', name='kind', kind=VALUE_WORDS, default='''line''', &
      choices='line helix points', meaning='analytic line, analytic helix, or spline fitted to points'), &
    declaration_t(groups='centerline', name='start', shape='3', unit='m', default='0, 0, 0', low=-1e6_wp, &
      high=1e6_wp, meaning='line: first end point (u is the arc length)'), &
    declaration_t(groups='centerline', name='end', shape='3', unit='m', default='10, 0, 0', low=-1e6_wp, &
      high=1e6_wp, meaning='line: last end point, at least 1 mm from `start`'), &
    declaration_t(groups='centerline', name='center', shape='3', unit='m', default='0, 0, 0', low=-1e6_wp, &
      high=1e6_wp, meaning='helix: a point on its (vertical) axis'), &
    declaration_t(groups='centerline', name='radius', unit='m', default='5', low=1e-3_wp, high=1e4_wp, &
      meaning='helix radius'), &
    declaration_t(groups='centerline', name='rise_per_turn', unit='m', default='0', low=-1e4_wp, high=1e4_wp, &
      meaning='helix rise per turn (negative: going down)'), &
    declaration_t(groups='centerline', name='turns', unit='1', default='0.25', low=0.0_wp, high=1e3_wp, &
      open_low=.true., meaning='helix turns; u is the angle in rad, in [0, 2 pi turns]'), &
    declaration_t(groups='centerline', name='phase_deg', unit='deg', default='-90', low=-360.0_wp, &
      high=360.0_wp, meaning='helix angle at u = 0'), &
    declaration_t(groups='centerline', name='horizon', shape='3', unit='1', default='0, 0, 1', low=-1e6_wp, &
      high=1e6_wp, meaning='horizon vector h of the frame (3.62): non-zero, never parallel to the tangent'), &
    declaration_t(groups='centerline', name='n_points', kind=VALUE_INTEGER, unit='1', &
      default='none', low=4.0_wp, high=real(max_centerline_points, wp), meaning='points: number of '// &
      'centerline points, the number given (required with `points`; left out: the lines of `points_file`)'), &
    declaration_t(groups='centerline', name='points', shape='3 per point', unit='m', default='none', &
      low=-1e6_wp, high=1e6_wp, meaning='points(:, i) = x, y, z of point i; no two consecutive equal'), &
    declaration_t(groups='centerline', name='points_file', kind=VALUE_WORDS, default='''''', &
      meaning='CSV file (relative to this input''s folder) instead of `points` and `horizon_points`: '// &
      '`x, y, z` or `x, y, z, hx, hy, hz` per line (docs/geometry.md)'), &
    declaration_t(groups='centerline', name='smoothing', unit='m^2', default='0', low=0.0_wp, high=1e6_wp, &
      meaning='FITPACK smoothing factor s (sum of squared distances allowed; 0 interpolates)'), &
    declaration_t(groups='centerline', name='degree', kind=VALUE_INTEGER, unit='1', default='5', low=3.0_wp, &
      high=5.0_wp, meaning='spline degree, odd when end tangents are given'), &
    declaration_t(groups='centerline', name='start_tangent', shape='3', unit='1', default='0, 0, 0', &
      low=-1e6_wp, high=1e6_wp, meaning='prescribed start direction of the spline (0: free)'), &
    declaration_t(groups='centerline', name='end_tangent', shape='3', unit='1', default='0, 0, 0', &
      low=-1e6_wp, high=1e6_wp, meaning='prescribed end direction of the spline (0: free)'), &
    declaration_t(groups='centerline', name='horizon_points', shape='3 per point', unit='1', &
      default='none', low=-1e6_wp, high=1e6_wp, meaning='points: one non-zero horizon vector per point, '// &
      'never parallel to the chord, fitted over the centerline''s parameter (none: `horizon`)'), &
    ! ---- &slide_elements (kind = 'slide'); a value an element does not use is 0 ('left')
    declaration_t(groups='slide_elements', name='n_elements', kind=VALUE_INTEGER, unit='1', &
      default='none', low=1.0_wp, high=real(max_elements, wp), &
      meaning='number of elements, the number of kinds given (or the rows of `elements_file`); required'), &
    declaration_t(groups='slide_elements', name='kind', kind=VALUE_WORDS, shape='one per element', &
      default='none', choices='straight curve helix runout drop bowl funnel patch', &
      meaning='element kind (a drop only first)'), &
    declaration_t(groups='slide_elements', name='length', shape='one per element', unit='m', default='0', &
      low=0.0_wp, high=1e4_wp, meaning='horizontal length, > 0 (straight, runout, funnel, patch)'), &
    declaration_t(groups='slide_elements', name='slope_deg', shape='one per element', unit='deg', &
      default='0', low=-45.0_wp, high=85.0_wp, meaning='downhill slope, > 0 goes down: in [-45, 45] (straight, '// &
      'curve, runout, funnel, patch); a drop''s top slope in [45, 85] (drop); the wall''s slope at the entry, in '// &
      '(0, 85] (bowl)'), &
    declaration_t(groups='slide_elements', name='radius', shape='one per element', unit='m', default='0', &
      low=0.0_wp, high=1e4_wp, meaning='horizontal radius, > 0 (curve, helix); the curve-out''s radius in '// &
      'its vertical plane, > 0 (drop); the entry''s distance from the axis, > 0 (bowl); the widest section''s '// &
      'radius, > the slide''s section''s (funnel)'), &
    declaration_t(groups='slide_elements', name='angle_deg', shape='one per element', unit='deg', &
      default='0', low=0.0_wp, high=720.0_wp, meaning='turning angle, >= 1e-6 (curve)'), &
    declaration_t(groups='slide_elements', name='direction', kind=VALUE_WORDS, shape='one per element', &
      default='''left''', choices='left right', meaning='turning direction (curve, helix, bowl)'), &
    declaration_t(groups='slide_elements', name='turns', shape='one per element', unit='1', default='0', &
      low=0.0_wp, high=100.0_wp, meaning='turns about the axis, > 0 (helix, bowl)'), &
    declaration_t(groups='slide_elements', name='drop', shape='one per element', unit='m', default='0', &
      low=-1e4_wp, high=1e4_wp, meaning='height lost over the helix, at most 2 pi radius turns (helix); over the '// &
      'whole drop, fall and curve-out, > 0 (drop); from the bowl''s entry to its outlet, > 0 (bowl)'), &
    declaration_t(groups='slide_elements', name='bowl_profile', kind=VALUE_WORDS, shape='one per element', &
      default='''sphere''', choices='sphere cone table', meaning='the bowl''s profile: a sphere, a cone or the '// &
      'quintic spline through `bowl_rho`, `bowl_z` (bowl)'), &
    declaration_t(groups='slide_elements', name='n_bowl_points', kind=VALUE_INTEGER, unit='1', default='none', &
      low=6.0_wp, high=real(max_profile_points, wp), meaning='the number of points of the bowls'' profile table, '// &
      'in `bowl_rho` and in `bowl_z`; only with a bowl_profile = ''table'''), &
    declaration_t(groups='slide_elements', name='bowl_rho', shape='one per bowl point', unit='m', &
      default='none', low=0.0_wp, high=1e4_wp, meaning='the profile table''s distances from the bowl''s axis, '// &
      'increasing (every table bowl of the chain)'), &
    declaration_t(groups='slide_elements', name='bowl_z', shape='one per bowl point', unit='m', &
      default='none', low=-1e4_wp, high=1e4_wp, meaning='the profile table''s heights of the wall, rising '// &
      'outward over the bowl'), &
    declaration_t(groups='slide_elements', name='patch_file', kind=VALUE_WORDS, shape='one per element', &
      default='''''', meaning='CSV file (relative to this input''s folder) of the patch''s offsets: `station, '// &
      'angle, offset` per line, a grid, 0 on its border (patch; docs/geometry.md)'), &
    declaration_t(groups='slide_elements', name='start', shape='3', unit='m', default='0, 0, 0', &
      low=-1e6_wp, high=1e6_wp, meaning='first centerline point'), &
    declaration_t(groups='slide_elements', name='heading_deg', unit='deg', default='0', low=-360.0_wp, &
      high=360.0_wp, meaning='first direction, from +x towards +y'), &
    declaration_t(groups='slide_elements', name='transition_length', unit='m', default='2', low=0.0_wp, &
      high=100.0_wp, meaning='horizontal length of each transition (0 only where no joint changes the slope or the '// &
      'curvature)'), &
    declaration_t(groups='slide_elements', name='centerline_kind', kind=VALUE_WORDS, default='''fitted''', &
      choices='fitted exact', meaning='fitted: a spline through points of the chain (the thesis); exact: '// &
      'the chain itself'), &
    declaration_t(groups='slide_elements', name='fit_spacing', unit='m', default='0.125', low=0.05_wp, &
      high=5.0_wp, meaning='horizontal spacing of the fitted points (fitted only)'), &
    declaration_t(groups='slide_elements', name='smoothing', unit='m^2', default='0', low=0.0_wp, &
      high=1e6_wp, meaning='smoothing factor of the fit (fitted only)'), &
    declaration_t(groups='slide_elements', name='degree', kind=VALUE_INTEGER, unit='1', default='5', &
      low=3.0_wp, high=5.0_wp, meaning='degree of the fit, 3 or 5 (fitted only)'), &
    declaration_t(groups='slide_elements', name='elements_file', kind=VALUE_WORDS, default='''''', &
      meaning='a manufacturer''s element table (CSV, docs/geometry.md) instead of `kind` … `drop`'), &
    ! ---- &cross_section (kind = 'tube' or 'slide')
    declaration_t(groups='cross_section', name='n_sections', kind=VALUE_INTEGER, unit='1', default='1', &
      low=1.0_wp, high=real(max_sections, wp), meaning='number of sections blended along the centerline, '// &
      'the number of kinds given'), &
    declaration_t(groups='cross_section', name='kind', kind=VALUE_WORDS, shape='one per section', &
      default='''circle'' (one section)', choices='circle ellipse flume profile', meaning='section kind'), &
    declaration_t(groups='cross_section', name='radius', shape='one per section', unit='m', default='0.5', &
      low=1e-3_wp, high=100.0_wp, meaning='circle radius; flume semicircle radius'), &
    declaration_t(groups='cross_section', name='half_width', shape='one per section', unit='m', &
      default='0.5', low=1e-3_wp, high=100.0_wp, meaning='ellipse: half width'), &
    declaration_t(groups='cross_section', name='half_height', shape='one per section', unit='m', &
      default='0.5', low=1e-3_wp, high=100.0_wp, meaning='ellipse: half height'), &
    declaration_t(groups='cross_section', name='wall', shape='one per section', unit='m', default='0.164', &
      low=1e-3_wp, high=100.0_wp, meaning='flume: length of the straight walls'), &
    declaration_t(groups='cross_section', name='joint_width_deg', shape='one per section', unit='deg', &
      default='2.865 (0.05 rad)', low=0.1_wp, high=20.0_wp, meaning='flume: 0.99-width of the smoothed joints'), &
    declaration_t(groups='cross_section', name='transition_midpoint', shape='one per transition', unit='m', &
      default='none', low=0.0_wp, high=1e6_wp, meaning='arc length where section j+1 has weight 1/2; within '// &
      'the centerline, transitions not overlapping'), &
    declaration_t(groups='cross_section', name='transition_end', shape='one per transition', unit='m', &
      default='none', low=0.0_wp, high=1e6_wp, meaning='arc length where its weight is 0.99, after the '// &
      'midpoint and within the centerline'), &
    declaration_t(groups='cross_section', name='n_profile', kind=VALUE_INTEGER, unit='1', default='none', &
      low=4.0_wp, high=real(max_profile_points, wp), meaning='profile: number of points in `profile_y` '// &
      'and in `profile_z`'), &
    declaration_t(groups='cross_section', name='profile_y', shape='one per profile point', unit='m', &
      default='none', low=-100.0_wp, high=100.0_wp, meaning='profile points across (y left); not '// &
      'self-intersecting, no point repeated'), &
    declaration_t(groups='cross_section', name='profile_z', shape='one per profile point', unit='m', &
      default='none', low=-100.0_wp, high=100.0_wp, meaning='profile points up (z); first = last closes it'), &
    declaration_t(groups='cross_section', name='profile_smoothing', unit='m^2', default='0', low=0.0_wp, &
      high=1e3_wp, meaning='smoothing factor of the profile fit'), &
    declaration_t(groups='cross_section', name='profile_degree', kind=VALUE_INTEGER, unit='1', default='5', &
      low=3.0_wp, high=5.0_wp, meaning='degree of the profile spline'), &
    ! ---- &blended (kind = 'blended')
    declaration_t(groups='blended', name='n_patches', kind=VALUE_INTEGER, unit='1', default='none', &
      low=2.0_wp, high=real(max_patches, wp), meaning='number of patches, the number of kinds given; required'), &
    declaration_t(groups='blended', name='kind', kind=VALUE_WORDS, shape='one per patch', default='none', &
      choices='ellipsoid elliptic_paraboloid hyperbolic_paraboloid elliptic_cylinder', &
      meaning='patch surface (as `&surface`)'), &
    declaration_t(groups='blended', name='a', shape='one per patch', unit='m', default='1', low=1e-3_wp, &
      high=1e4_wp, meaning='first semi-axis, as in `&surface`'), &
    declaration_t(groups='blended', name='b', shape='one per patch', unit='m', default='1', low=1e-3_wp, &
      high=1e4_wp, meaning='second semi-axis, as in `&surface`'), &
    declaration_t(groups='blended', name='c', shape='one per patch', unit='m', default='1', low=1e-3_wp, &
      high=1e4_wp, meaning='third semi-axis (ellipsoids only)'), &
    declaration_t(groups='blended', name='origin', shape='3 per patch', unit='m', default='0, 0, 0', &
      low=-1e6_wp, high=1e6_wp, meaning='placement of the patch'), &
    declaration_t(groups='blended', name='angles_deg', shape='3 per patch', unit='deg', default='0, 0, 0', &
      low=-360.0_wp, high=360.0_wp, meaning='Cardan angles of the patch, R = Rx Ry Rz'), &
    declaration_t(groups='blended', name='u_min', shape='one per patch', unit='patch parameter units', &
      default='0', low=-1e4_wp, high=1e4_wp, meaning='start of the part of the patch used in u'), &
    declaration_t(groups='blended', name='u_max', shape='one per patch', unit='patch parameter units', &
      default='1', low=-1e4_wp, high=1e4_wp, meaning='end of the part used in u, more than `u_min`'), &
    declaration_t(groups='blended', name='v_min', shape='one per patch', unit='patch parameter units', &
      default='0', low=-1e4_wp, high=1e4_wp, meaning='patch v mapped to blend v = 0'), &
    declaration_t(groups='blended', name='v_max', shape='one per patch', unit='patch parameter units', &
      default='1', low=-1e4_wp, high=1e4_wp, meaning='patch v mapped to blend v = 1, not `v_min` (may be less)'), &
    declaration_t(groups='blended', name='swap_uv', kind=VALUE_LOGICAL, shape='one per patch', &
      default='.false.', meaning='evaluate the patch at (v, u) (thesis fig. 3.16)'), &
    declaration_t(groups='blended', name='transition', shape='one per transition', unit='blend u', &
      default='0', low=0.0_wp, high=1e4_wp, meaning='length of the transition between patch j and j+1'), &
    declaration_t(groups='blended', name='midpoint', shape='one per transition', unit='blend u', &
      default='none', low=-1e4_wp, high=1e4_wp, &
      meaning='logistic transition: where it is half done (with `u_99`; none: the middle of each transition)'), &
    declaration_t(groups='blended', name='u_99', shape='one per transition', unit='blend u', &
      default='none', low=-1e4_wp, high=1e4_wp, &
      meaning='logistic transition: where it is 99 % done, after `midpoint` (none: the end of each transition)'), &
    ! ---- &bspline (kind = 'bspline')
    declaration_t(groups='bspline', name='file', kind=VALUE_WORDS, default='''''', &
      meaning='CSV file with the points (relative to this input''s folder), required; every cell -1e6 … 1e6 m'), &
    declaration_t(groups='bspline', name='layout', kind=VALUE_WORDS, default='''scattered''', &
      choices='scattered grid parametric', meaning='`x, y, z` fitted as z = s(x, y) (scattered or grid), or '// &
      '`u, v, x, y, z` (parametric)'), &
    declaration_t(groups='bspline', name='smoothing', unit='m^2', default='0', low=0.0_wp, high=1e6_wp, &
      meaning='FITPACK smoothing factor (sum of squared residuals)'), &
    declaration_t(groups='bspline', name='degree', kind=VALUE_INTEGER, unit='1', default='3', low=1.0_wp, &
      high=5.0_wp, meaning='degree (scattered, grid; parametric is bicubic)'), &
    declaration_t(groups='bspline', name='periodic_u', kind=VALUE_LOGICAL, default='.false.', &
      meaning='parametric only: closed in u (last grid line = first)'), &
    declaration_t(groups='bspline', name='periodic_v', kind=VALUE_LOGICAL, default='.false.', &
      meaning='parametric only: closed in v (last grid line = first)')]
end module io_declarations_geometry
