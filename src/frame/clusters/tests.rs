use super::*;
use crate::math;
use crate::math::lcg::Lcg;

fn camera() -> (Mat4, Mat4, f32, f32) {
    let view = math::look_at(Vec3::new(0.0, 4.0, 10.0), Vec3::ZERO, Vec3::Y);
    (
        view,
        math::perspective(55f32.to_radians(), 16.0 / 9.0, 0.5, 60.0),
        0.5,
        60.0,
    )
}

fn ortho() -> (Mat4, Mat4, f32, f32) {
    let view = math::look_at(Vec3::new(0.0, 4.0, 10.0), Vec3::ZERO, Vec3::Y);
    (
        view,
        math::orthographic(-8.0, 8.0, -4.5, 4.5, 0.5, 40.0),
        0.5,
        40.0,
    )
}

/// Every point of every sphere that lands on a pixel of the view must find
/// its light in that pixel's cluster: sample points inside the spheres,
/// project them as the rasteriser would, look the cluster up as the shader does.
fn assert_conservative(cam: (Mat4, Mat4, f32, f32), tile: u32, slices: u32, bounds: &[Bound]) {
    let (view, projection, near, far) = cam;
    let size = (320, 180);
    let grid = Grid::new(size.0, size.1, tile, slices, near, far);
    let bins = bin(&grid, view, projection, size, bounds);
    let mut rng = Lcg(11);
    let mut checked = 0;
    for (i, b) in bounds.iter().enumerate() {
        let (centre, radius) = match *b {
            Bound::Sphere(c, r) => (c, r),
            Bound::Everywhere => {
                assert!(bins.indices[..bins.global as usize].contains(&(i as u32)));
                continue;
            }
            Bound::Apart => {
                assert!(!bins.indices.contains(&(i as u32)));
                continue;
            }
        };
        for _ in 0..4000 {
            // A point in the ball (its surface included).
            let d = Vec3::new(
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
            );
            if d.length() > 1.0 {
                continue;
            }
            let d = if rng.next() < 0.3 {
                d.normalize_or_zero()
            } else {
                d
            };
            let p = centre + d * radius;
            let e = view.transform_point3(p);
            let depth = -e.z;
            if depth < near || depth > far {
                continue;
            }
            let clip = projection * e.extend(1.0);
            let ndc = clip.truncate() / clip.w;
            let (px, py) = (
                (ndc.x * 0.5 + 0.5) * size.0 as f32,
                (ndc.y * 0.5 + 0.5) * size.1 as f32,
            );
            if px < 0.0 || py < 0.0 || px >= size.0 as f32 || py >= size.1 as f32 {
                continue;
            }
            let (tx, ty) = (px as u32 / tile, py as u32 / tile);
            let c = bins.clusters[grid.index(tx, ty, grid.slice_of(depth))];
            let list = &bins.indices[c[0] as usize..(c[0] + c[1]) as usize];
            assert!(
                list.contains(&(i as u32)),
                "light {i} (centre {centre}, radius {radius}) missing from tile ({tx}, {ty}) slice {} at depth {depth}",
                grid.slice_of(depth)
            );
            checked += 1;
        }
    }
    assert!(checked > 1000, "only {checked} points landed in view");
}

fn random_spheres(seed: u64, n: usize, radius: (f32, f32)) -> Vec<Bound> {
    let mut rng = Lcg(seed);
    (0..n)
        .map(|_| {
            Bound::Sphere(
                Vec3::new(
                    rng.range(-12.0, 12.0),
                    rng.range(-1.0, 6.0),
                    rng.range(-20.0, 12.0),
                ),
                rng.range(radius.0, radius.1),
            )
        })
        .collect()
}

#[test]
fn every_point_a_light_reaches_finds_it_in_its_cluster() {
    let spheres = random_spheres(3, 60, (0.2, 4.0));
    for (tile, slices) in [(16, 1), (16, 16), (7, 5), (64, 32)] {
        assert_conservative(camera(), tile, slices, &spheres);
        assert_conservative(ortho(), tile, slices, &spheres);
    }
}

#[test]
fn hard_cases_stay_conservative() {
    let (view, ..) = camera();
    let eye = Vec3::new(0.0, 4.0, 10.0);
    let inv = view.inverse();
    let spheres = vec![
        // The eye inside a light's sphere, and the near plane through one.
        Bound::Sphere(eye, 3.0),
        Bound::Sphere(inv.transform_point3(Vec3::new(0.3, -0.2, -0.6)), 0.5),
        // A sphere behind the eye (culled), one past the far plane (culled).
        Bound::Sphere(inv.transform_point3(Vec3::new(0.0, 0.0, 5.0)), 1.0),
        Bound::Sphere(inv.transform_point3(Vec3::new(0.0, 0.0, -80.0)), 1.0),
        // Centred exactly on a tile corner and a slice boundary.
        Bound::Sphere(Vec3::ZERO, 1.0),
        // Tiny and huge.
        Bound::Sphere(Vec3::new(1.0, 0.0, 0.0), 1e-4),
        Bound::Sphere(Vec3::new(0.0, 0.0, -5.0), 500.0),
        // Past what f32 squares (a cutoff of 1e-45 gives such radii).
        Bound::Sphere(Vec3::new(3.0, 1.0, 2.0), 1e30),
        // No radius: every pixel; a caster: apart.
        Bound::Everywhere,
        Bound::Apart,
    ];
    assert_conservative(camera(), 16, 16, &spheres);
    let (view, projection, near, far) = camera();
    let grid = Grid::new(320, 180, 16, 16, near, far);
    let bins = bin(&grid, view, projection, (320, 180), &spheres);
    assert_eq!(bins.global, 1);
    assert_eq!(bins.indices[0], 8);
    assert_eq!(bins.culled, 2, "behind the eye and past the far plane");
    assert!(
        !bins.indices.contains(&9),
        "a light kept apart is listed nowhere"
    );
    // The huge spheres are in every cluster.
    for light in [6, 7] {
        assert!(
            bins.clusters
                .iter()
                .all(|c| { bins.indices[c[0] as usize..(c[0] + c[1]) as usize].contains(&light) })
        );
    }
}

#[test]
fn binning_is_tight_where_lights_are_small() {
    // 1000 small lights in a 24 x 24 area: a pixel's cluster lists a few,
    // not hundreds; the same lights in one tile would list them all.
    let spheres = random_spheres(5, 1000, (0.3, 0.6));
    let (view, projection, near, far) = camera();
    let grid = Grid::new(1280, 720, 16, 16, near, far);
    let bins = bin(&grid, view, projection, (1280, 720), &spheres);
    assert!(
        bins.mean_per_cluster() < 4.0,
        "mean {}",
        bins.mean_per_cluster()
    );
    assert!(
        bins.max_per_cluster() < 40,
        "max {}",
        bins.max_per_cluster()
    );
}

#[test]
fn slices_are_exponential_and_match_slice_of() {
    let g = Grid::new(100, 100, 10, 8, 0.5, 128.0);
    assert_eq!(g.slice_start(0), 0.5);
    assert!(
        (g.slice_start(4) - 8.0).abs() < 1e-4,
        "{}",
        g.slice_start(4)
    );
    assert_eq!(g.slice_start(8), 128.0);
    for k in 0..8 {
        let mid = (g.slice_start(k) * g.slice_start(k + 1)).sqrt();
        assert_eq!(g.slice_of(mid), k);
    }
    assert_eq!(g.slice_of(0.01), 0);
    assert_eq!(g.slice_of(1e9), 7);
    assert_eq!(Grid::new(100, 100, 10, 1, 0.5, 128.0).slice_of(50.0), 0);
}

#[test]
fn lists_that_do_not_fit_coarsen_the_grid_until_they_do() {
    let spheres = random_spheres(9, 300, (1.0, 3.0));
    let (view, projection, near, far) = camera();
    let grid = Grid::new(320, 180, 8, 16, near, far);
    let (full, bins) = bin_within(&grid, view, projection, (320, 180), &spheres, usize::MAX);
    assert_eq!(full, grid);
    let limit = bins.indices.len() / 4;
    let (coarse, small) = bin_within(&grid, view, projection, (320, 180), &spheres, limit);
    assert!(coarse.tile_size > grid.tile_size && coarse.slices < grid.slices);
    assert!(small.indices.len() <= limit);
    // At the very least one cluster holding every visible light.
    let (one, all) = bin_within(&grid, view, projection, (320, 180), &spheres, 1);
    assert_eq!((one.tiles, one.slices), ((1, 1), 1));
    assert_eq!(all.indices.len() as u32 + all.culled, 300);
}
