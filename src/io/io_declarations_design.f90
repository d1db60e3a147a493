!> The declarations of the design groups (io_declaration): &optimize,
!> &design_elements and &catalogue (an optimisation over element parameters
!> and its standard parts), and
!> &identify
!> is read by two scenarios with different variables, declared as the
!> tables identify_rider and identify_water (the variables both have are
!> declared once for both). What a fit estimates takes the range of the
!> variable it estimates: twin_mu and the bounds of mu_D that of &rider mu,
!> twin_f and the bounds of f that of &water f1 (f2 and f3 have the same;
!> test_input_declarations checks it).
module io_declarations_design
  use base_kinds, only: wp
  use geometry_slide_elements, only: max_element_slope_deg
  use io_declaration, only: declaration_t, VALUE_REAL, VALUE_INTEGER, VALUE_LOGICAL, VALUE_WORDS
  implicit none (type, external)
  private
  public :: design_declarations

  type(declaration_t), parameter :: design_declarations(*) = [ &
    ! ---- the measurements: files or lists
    declaration_t(groups='identify_rider', name='stations_file', kind=VALUE_WORDS, default='none', &
      meaning='CSV of the stations: arc_length (m), pelvis, heels, back wall angle (rad); a header line '// &
      'allowed; relative to the input''s folder'), &
    declaration_t(groups='identify_rider', name='station_arc_length', shape='list of at most 10000', unit='m', &
      default='none', low=0.0_wp, high=1e6_wp, meaning='the stations, when no file: increasing, after the '// &
      'rider''s start'), &
    declaration_t(groups='identify_rider', name='pelvis_angle', shape='one per station', unit='rad', &
      default='none', low=-4.0_wp, high=4.0_wp, meaning='the measured wall angle of the pelvis (+ towards +v)'), &
    declaration_t(groups='identify_rider', name='heels_angle', shape='one per station', unit='rad', &
      default='none', low=-4.0_wp, high=4.0_wp, meaning='the measured wall angle of the heels'), &
    declaration_t(groups='identify_rider', name='back_angle', shape='one per station', unit='rad', &
      default='none', low=-4.0_wp, high=4.0_wp, meaning='the measured wall angle of the back'), &
    declaration_t(groups='identify_water', name='sections_file', kind=VALUE_WORDS, default='none', &
      meaning='CSV of the sections: arc_length (m), v (rad, the middle of the flow); a header line allowed; '// &
      'relative to the input''s folder'), &
    declaration_t(groups='identify_water', name='section_arc_length', shape='list of at most 10000', unit='m', &
      default='none', low=0.0_wp, high=1e6_wp, meaning='the sections, when no file: increasing'), &
    declaration_t(groups='identify_water', name='section_v', shape='one per section', unit='rad', &
      default='none', low=-4.0_wp, high=8.0_wp, meaning='the measured middle of the flow (pi/2: the bottom)'), &
    declaration_t(groups='identify_rider identify_water', name='segments_file', kind=VALUE_WORDS, &
      default='none', meaning='CSV of the segments: start (m), end (m), speed (m/s)'), &
    declaration_t(groups='identify_rider identify_water', name='segment_start', shape='list of at most 1000', &
      unit='m', default='none', low=0.0_wp, high=1e6_wp, meaning='where each measured segment starts, when no file'), &
    declaration_t(groups='identify_rider identify_water', name='segment_end', shape='one per segment', unit='m', &
      default='none', low=0.0_wp, high=1e6_wp, meaning='where it ends, after its start'), &
    declaration_t(groups='identify_rider identify_water', name='segment_speed', shape='one per segment', &
      unit='m/s', default='none', low=0.0_wp, high=100.0_wp, open_low=.true., &
      meaning='the speed measured over it'), &
    ! ---- twin experiments: the true value of what is fitted
    declaration_t(groups='identify_rider', name='twin_mu', range_of='sweep mu', default='none', &
      meaning='a twin experiment: the angles and speeds are simulated with this mu_D (noise-free); angles, '// &
      'speeds and files are refused then'), &
    declaration_t(groups='identify_water', name='twin_f', range_of='water f1', shape='3: f1, f2, f3', &
      unit='kg/m, kg, kg m', default='none', meaning='a twin experiment: the measurements are simulated with '// &
      'these f (noise-free); values and files are refused then'), &
    ! ---- the fits
    declaration_t(groups='identify_rider', name='weight', unit='1', default='0.6', low=0.0_wp, high=1.0_wp, &
      meaning='w_RP of (4.43) (0 without segments, 1 without stations)'), &
    declaration_t(groups='identify_water', name='weight', unit='1', default='0.8', low=0.0_wp, high=1.0_wp, &
      meaning='w of (4.34) (0 without segments, 1 without sections)'), &
    declaration_t(groups='identify_rider', name='k2', unit='rad s/m', default='1', low=0.0_wp, high=100.0_wp, &
      open_low=.true., meaning='k2 of (4.43)'), &
    declaration_t(groups='identify_water', name='k1', unit='rad s/m', default='1', low=0.0_wp, high=100.0_wp, &
      open_low=.true., meaning='k1 of (4.34)'), &
    declaration_t(groups='identify_rider', name='lower', range_of='sweep mu', default='0', &
      meaning='lower bound of mu_D, held exactly'), &
    declaration_t(groups='identify_rider', name='upper', range_of='sweep mu', default='0.11', &
      meaning='upper bound of mu_D, held exactly, above `lower` (thesis table 4.8)'), &
    declaration_t(groups='identify_water', name='estimate', kind=VALUE_LOGICAL, shape='3: f1, f2, f3', &
      default='.true., .true., .true.', meaning='which of f1, f2, f3 are fitted (the others stay at their start)'), &
    declaration_t(groups='identify_water', name='lower', range_of='water f1', shape='3: f1, f2, f3', &
      unit='kg/m, kg, kg m', default='0, 0, 0', meaning='lower bounds of f, held exactly'), &
    declaration_t(groups='identify_water', name='upper', range_of='water f1', shape='3: f1, f2, f3', &
      unit='kg/m, kg, kg m', default='none', meaning='upper bounds of f, held exactly, above `lower`; none: '// &
      'one-sided (table 4.3)'), &
    declaration_t(groups='identify_water', name='speed', kind=VALUE_WORDS, default='''midpoint''', &
      choices='midpoint passage', meaning='the simulated speed: at the segment''s midpoint (the thesis) or its '// &
      'length over the passage time'), &
    declaration_t(groups='identify_water', name='middle', kind=VALUE_WORDS, default='''edges''', &
      choices='edges streamline', meaning='the simulated middle: the mean of the computed edges'' v or the '// &
      'streamline''s own v'), &
    declaration_t(groups='identify_water', name='sweep_weights', shape='list of at most 100', unit='1', &
      default='none', low=0.0_wp, high=1.0_wp, meaning='the weight sweep of table 4.2: one fit per weight'), &
    declaration_t(groups='identify_rider identify_water', name='ftol', unit='1', default='1e-8', low=0.0_wp, &
      high=1.0_wp, open_low=.true., meaning='LMDER''s tolerance on the sum of squares'), &
    declaration_t(groups='identify_rider identify_water', name='xtol', unit='1', default='1e-8', low=0.0_wp, &
      high=1.0_wp, open_low=.true., meaning='LMDER''s tolerance on the parameters'), &
    declaration_t(groups='identify_rider identify_water', name='threads', kind=VALUE_INTEGER, unit='1', &
      default='1', low=1.0_wp, high=1024.0_wp, meaning='OpenMP threads (the rides of the differences)'), &
    declaration_t(groups='identify_rider', name='sensitivity', kind=VALUE_LOGICAL, default='.false.', &
      meaning='the body-parameter study of table 4.10 at the identified mu_D'), &
    ! ---- &optimize (thesis 4.7; the defaults are table 4.12 and (4.49))
    declaration_t(groups='optimize', name='n_points', kind=VALUE_INTEGER, unit='1', default='9', low=4.0_wp, &
      high=200.0_wp, meaning='number of centerline points (with `points`)'), &
    declaration_t(groups='optimize', name='points', shape='3 per point', unit='m', default='table 4.12', &
      low=-1e5_wp, high=1e5_wp, meaning='the points, x, y, z each (`points(:, i)`)'), &
    declaration_t(groups='optimize', name='n_design', kind=VALUE_INTEGER, unit='1', default='5', low=1.0_wp, &
      high=50.0_wp, meaning='number of design variables (with all four of their lists)'), &
    declaration_t(groups='optimize', name='design_point', shape='per design variable', unit='1', &
      default='2, 3, 4, 5, 6', low=0.0_wp, high=199.0_wp, &
      meaning='the point of each design variable (0 = the first), a whole number below `n_points`'), &
    declaration_t(groups='optimize', name='design_coordinate', kind=VALUE_WORDS, shape='per design variable', &
      default='y, y, x, y, y', choices='x y z', meaning='its coordinate'), &
    declaration_t(groups='optimize', name='lower', shape='per design variable', unit='m', &
      default='4, 4, 5, 8, 8', low=-1e5_wp, high=1e5_wp, meaning='lower bound of each, held exactly, at most '// &
      'its start value'), &
    declaration_t(groups='optimize', name='upper', shape='per design variable', unit='m', &
      default='6, 6, 7, 10, 10', low=-1e5_wp, high=1e5_wp, meaning='upper bound of each, above `lower`, at '// &
      'least its start value'), &
    declaration_t(groups='optimize', name='radius', unit='m', default='0.7', low=0.0_wp, high=100.0_wp, &
      open_low=.true., meaning='tube radius (circular section)'), &
    declaration_t(groups='optimize', name='degree', kind=VALUE_INTEGER, unit='1', default='5', low=3.0_wp, &
      high=5.0_wp, meaning='degree of the centerline spline, below `n_points`'), &
    declaration_t(groups='optimize', name='smoothing', unit='m^2', default='0', low=0.0_wp, high=1e6_wp, &
      meaning='FITPACK smoothing factor (0 interpolates)'), &
    declaration_t(groups='optimize', name='horizon', shape='3', unit='1', default='0, 0, 1', low=-1e6_wp, &
      high=1e6_wp, meaning='horizon vector of the tube''s frames, not zero'), &
    declaration_t(groups='optimize', name='start_angles_deg', shape='list of at most 50', unit='deg', &
      default='-30, -15, 0, 15, 30', low=-89.0_wp, high=89.0_wp, &
      meaning='one ride each: the start direction to the centerline; at least n_design/2 rides'), &
    declaration_t(groups='optimize', name='start_speed', unit='m/s', default='0.5', low=0.0_wp, high=100.0_wp, &
      meaning='start speed of every ride'), &
    declaration_t(groups='optimize', name='start_wall_angle_deg', unit='deg', default='0', low=-170.0_wp, &
      high=170.0_wp, meaning='where on the first section the rides start (0 the bottom, + towards +v)'), &
    declaration_t(groups='optimize', name='body_mass', unit='kg', default='90', low=0.0_wp, high=1e4_wp, &
      open_low=.true., meaning='the cuboid''s mass'), &
    declaration_t(groups='optimize', name='body_length', unit='m', default='1.8', low=0.0_wp, high=100.0_wp, &
      open_low=.true., meaning='the cuboid''s side along the slide'), &
    declaration_t(groups='optimize', name='body_width', unit='m', default='0.5', low=0.0_wp, high=100.0_wp, &
      open_low=.true., meaning='its side across'), &
    declaration_t(groups='optimize', name='body_height', unit='m', default='0.2', low=0.0_wp, high=100.0_wp, &
      open_low=.true., meaning='its side along the normal'), &
    declaration_t(groups='optimize', name='com_height', unit='m', default='0.1', low=0.0_wp, high=100.0_wp, &
      meaning='its centre of mass above the surface'), &
    declaration_t(groups='optimize', name='acceleration', kind=VALUE_WORDS, default='''kinematic''', &
      choices='kinematic felt', meaning='|a_D| or |a_D - g| in (4.49)'), &
    declaration_t(groups='optimize', name='constraint', kind=VALUE_WORDS, default='''penalty''', &
      choices='penalty exact none', meaning='how the lever-arm limit is kept'), &
    declaration_t(groups='optimize', name='lever_limit', unit='m', default='0.25', low=0.0_wp, high=10.0_wp, &
      open_low=.true., meaning='largest tipping lever arm (half the body''s width)'), &
    declaration_t(groups='optimize', name='penalty_factor', unit='m/s^2 per m', default='5e3', low=0.0_wp, &
      high=1e12_wp, open_low=.true., meaning='the thesis''s penalty factor'), &
    declaration_t(groups='optimize', name='lever_tolerance', unit='m', default='1e-4', low=0.0_wp, high=1.0_wp, &
      open_low=.true., meaning='largest tipping excess accepted at the end (the constraint check)'), &
    declaration_t(groups='optimize', name='population_cost', kind=VALUE_WORDS, &
      default='''worst'' with &sweep, else ''sum''', choices='sum worst quantile', &
      meaning='the acceleration part of the cost over the rides: their sum (4.49), the worst ride, or the '// &
      '`quantile` of the rides (docs/design.md, "Robust design over a population")'), &
    declaration_t(groups='optimize', name='quantile', unit='1', default='0.9', low=0.0_wp, high=1.0_wp, &
      meaning='q of `population_cost = ''quantile''` (1 the worst ride), linear between the rides'), &
    declaration_t(groups='optimize', name='threads', kind=VALUE_INTEGER, unit='1', default='1', low=1.0_wp, &
      high=1024.0_wp, meaning='OpenMP threads for the rides and the difference points (or the starts)'), &
    declaration_t(groups='optimize', name='ftol', unit='1', default='1e-4', low=1e-15_wp, high=1.0_wp, &
      meaning='LMDER''s tolerance on the cost; also decides whether a restart made progress'), &
    declaration_t(groups='optimize', name='xtol', unit='1', default='1e-3', low=1e-15_wp, high=1.0_wp, &
      meaning='LMDER''s tolerance on the design'), &
    declaration_t(groups='optimize', name='max_designs', kind=VALUE_INTEGER, unit='1', default='10000', &
      low=1.0_wp, high=1e6_wp, meaning='designs LMDER may ask for per start, restarts and differences included'), &
    declaration_t(groups='optimize', name='max_restarts', kind=VALUE_INTEGER, unit='1', default='10', &
      low=1.0_wp, high=100.0_wp, meaning='restarts from the end point to show it is a minimum'), &
    declaration_t(groups='optimize', name='starts', kind=VALUE_INTEGER, unit='1', default='1', low=1.0_wp, &
      high=1000.0_wp, meaning='multi-start: the given design and starts - 1 drawn ones'), &
    declaration_t(groups='optimize', name='seed', kind=VALUE_INTEGER, unit='1', default='1', low=1.0_wp, &
      high=2147483647.0_wp, meaning='the stream the drawn starts come from; only with `starts` > 1'), &
    ! ---- &design_elements: element parameters as the design variables (with &slide_elements)
    declaration_t(groups='design_elements', name='n_design', kind=VALUE_INTEGER, unit='1', default='none', &
      low=1.0_wp, high=50.0_wp, meaning='number of design variables (with all four of their lists)'), &
    declaration_t(groups='design_elements', name='element', shape='per design variable', &
      unit='1', default='none', low=1.0_wp, high=40.0_wp, &
      meaning='the element of &slide_elements of each design variable (1 = the first)'), &
    declaration_t(groups='design_elements', name='parameter', kind=VALUE_WORDS, shape='per design variable', &
      default='none', choices='length slope radius angle drop', meaning='its parameter, as &slide_elements '// &
      'names it: length (m; straight, runout, funnel), slope (deg; straight, curve, runout, funnel, bowl, drop), '// &
      'radius (m; curve, helix, bowl, funnel, drop), angle (deg; curve), drop (m; bowl)'), &
    declaration_t(groups='design_elements', name='lower', shape='per design variable', unit='m or deg', &
      default='none', low=-720.0_wp, high=1e4_wp, meaning='lower bound of each, in its parameter''s unit, held '// &
      'exactly, at most its start value (&slide_elements), inside what its element''s kind allows (as '// &
      '&slide_elements: a straight''s slope in [-45, 45] deg, ...)'), &
    declaration_t(groups='design_elements', name='upper', shape='per design variable', unit='m or deg', &
      default='none', low=-720.0_wp, high=1e4_wp, meaning='upper bound of each, above `lower`, at least its '// &
      'start value, inside what its element''s kind allows'), &
    ! ---- &catalogue: the standard parts (docs/design.md, "Designs from standard parts")
    declaration_t(groups='catalogue', name='radii', shape='list of at most 200', unit='m', default='none', &
      low=0.0_wp, high=1e4_wp, open_low=.true., meaning='the radii made (curve, helix; increasing); or radius_step'), &
    declaration_t(groups='catalogue', name='radius_step', unit='m', default='none', low=0.0_wp, high=1e4_wp, &
      open_low=.true., meaning='radii made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='angles_deg', shape='list of at most 200', unit='deg', default='none', &
      low=0.0_wp, high=720.0_wp, open_low=.true., meaning='the turning angles made (increasing); or angle_step_deg'), &
    declaration_t(groups='catalogue', name='angle_step_deg', unit='deg', default='none', low=0.0_wp, &
      high=720.0_wp, open_low=.true., meaning='turning angles made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='slopes_deg', shape='list of at most 200', unit='deg', default='none', &
      low=-max_element_slope_deg, high=max_element_slope_deg, meaning='the slopes made (straight, curve, '// &
      'runout, funnel: the slope &slide_elements takes for them; increasing); or slope_step_deg'), &
    declaration_t(groups='catalogue', name='slope_step_deg', unit='deg', default='none', low=0.0_wp, &
      high=max_element_slope_deg, open_low=.true., meaning='slopes made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='lengths', shape='list of at most 200', unit='m', default='none', &
      low=0.0_wp, high=1e4_wp, open_low=.true., meaning='the lengths made (increasing); or length_step'), &
    declaration_t(groups='catalogue', name='length_step', unit='m', default='none', low=0.0_wp, high=1e4_wp, &
      open_low=.true., meaning='lengths made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='bowl_radii', shape='list of at most 200', unit='m', default='none', &
      low=0.0_wp, high=1e4_wp, open_low=.true., meaning='the bowls made: their entry radii from the axis '// &
      '(increasing); or bowl_radius_step'), &
    declaration_t(groups='catalogue', name='bowl_radius_step', unit='m', default='none', low=0.0_wp, high=1e4_wp, &
      open_low=.true., meaning='bowls'' entry radii made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='bowl_slopes_deg', shape='list of at most 200', unit='deg', &
      default='none', low=0.0_wp, high=85.0_wp, open_low=.true., meaning='the bowls made: their wall slopes at '// &
      'the entry (increasing); or bowl_slope_step_deg'), &
    declaration_t(groups='catalogue', name='bowl_slope_step_deg', unit='deg', default='none', low=0.0_wp, &
      high=85.0_wp, open_low=.true., meaning='bowls'' wall slopes made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='bowl_drops', shape='list of at most 200', unit='m', default='none', &
      low=0.0_wp, high=1e4_wp, open_low=.true., meaning='the bowls made: their drops from the entry to the '// &
      'outlet (increasing); or bowl_drop_step'), &
    declaration_t(groups='catalogue', name='bowl_drop_step', unit='m', default='none', low=0.0_wp, high=1e4_wp, &
      open_low=.true., meaning='bowls'' drops made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='funnel_lengths', shape='list of at most 200', unit='m', &
      default='none', low=0.0_wp, high=1e4_wp, open_low=.true., meaning='the funnels made: their lengths '// &
      '(increasing); or funnel_length_step'), &
    declaration_t(groups='catalogue', name='funnel_length_step', unit='m', default='none', low=0.0_wp, &
      high=1e4_wp, open_low=.true., meaning='funnels'' lengths made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='funnel_radii', shape='list of at most 200', unit='m', default='none', &
      low=0.0_wp, high=1e4_wp, open_low=.true., meaning='the funnels made: their widest radii (increasing); or '// &
      'funnel_radius_step'), &
    declaration_t(groups='catalogue', name='funnel_radius_step', unit='m', default='none', low=0.0_wp, &
      high=1e4_wp, open_low=.true., meaning='funnels'' widest radii made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='drop_slopes_deg', shape='list of at most 200', unit='deg', &
      default='none', low=45.0_wp, high=85.0_wp, meaning='the drops made: their fall''s slopes (increasing); or '// &
      'drop_slope_step_deg'), &
    declaration_t(groups='catalogue', name='drop_slope_step_deg', unit='deg', default='none', low=0.0_wp, &
      high=85.0_wp, open_low=.true., meaning='drops'' fall slopes made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='drop_radii', shape='list of at most 200', unit='m', default='none', &
      low=0.0_wp, high=1e4_wp, open_low=.true., meaning='the drops made: their curve-out radii (increasing); or '// &
      'drop_radius_step'), &
    declaration_t(groups='catalogue', name='drop_radius_step', unit='m', default='none', low=0.0_wp, high=1e4_wp, &
      open_low=.true., meaning='drops'' curve-out radii made: the whole multiples of it'), &
    declaration_t(groups='catalogue', name='max_designs', kind=VALUE_INTEGER, unit='1', default='64', &
      low=1.0_wp, high=100000.0_wp, meaning='designs of the neighbourhood of the nearest catalogue design '// &
      'ridden at most (3^n_design for all)')]
end module io_declarations_design
