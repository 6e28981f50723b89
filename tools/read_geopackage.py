# Reads a GeoPackage procex wrote with GDAL/OGR's own Python bindings, as a
# GIS would, and writes what it found as JSON: the layers' CRS (as WKT, and
# whether it is the same CRS as one given), and per building its attributes
# with their OGR types, its 3D envelope, the volume its polygons enclose
# (divergence theorem, computed here from the coordinates read back), its
# centroid in longitude/latitude (PROJ through OSR), and its surfaces'
# counts per tag.
#
#   python3 tools/read_geopackage.py FILE.gpkg "CRS procex was given" OUT.json
import json
import sys

from osgeo import ogr, osr

ogr.UseExceptions()
osr.UseExceptions()


def ring_volume(points):
    # Fan of the ring (closed: the last point repeats the first) about its first corner.
    v = 0.0
    p0 = points[0]
    for a, b in zip(points[1:-2], points[2:-1]):
        v += (p0[0] * (a[1] * b[2] - a[2] * b[1]) - p0[1] * (a[0] * b[2] - a[2] * b[0]) +
              p0[2] * (a[0] * b[1] - a[1] * b[0])) / 6.0
    return v


def main():
    path, crs_text, out = sys.argv[1:4]
    ds = ogr.Open(path)
    given = osr.SpatialReference()
    given.SetFromUserInput(crs_text)
    wgs84 = osr.SpatialReference()
    wgs84.ImportFromEPSG(4326)
    wgs84.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    result = {'layers': {}, 'buildings': {}}
    for i in range(ds.GetLayerCount()):
        layer = ds.GetLayer(i)
        srs = layer.GetSpatialRef()
        result['layers'][layer.GetName()] = {
            'features': layer.GetFeatureCount(),
            'geometry': ogr.GeometryTypeToName(layer.GetGeomType()),
            'crs_same': bool(srs is not None and srs.IsSame(given)),
            'crs': srs.ExportToWkt() if srs is not None else None,
        }
    shells = ds.GetLayerByName('buildings')
    srs = shells.GetSpatialRef()
    srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    to_lonlat = osr.CoordinateTransformation(srs, wgs84)
    defn = shells.GetLayerDefn()
    for f in shells:
        g = f.GetGeometryRef()
        volume = 0.0
        for k in range(g.GetGeometryCount()):
            volume += ring_volume(g.GetGeometryRef(k).GetGeometryRef(0).GetPoints())
        env = g.GetEnvelope3D()  # (minx, maxx, miny, maxy, minz, maxz)
        c = g.Centroid()
        lon, lat, _ = to_lonlat.TransformPoint(c.GetX(), c.GetY(), 0.0)
        attributes = {}
        for k in range(defn.GetFieldCount()):
            field = defn.GetFieldDefn(k)
            type_name = field.GetFieldTypeName(field.GetType())
            if field.GetSubType() == ogr.OFSTBoolean:
                type_name = 'Boolean'
            attributes[field.GetName()] = {'type': type_name, 'value': f.GetField(k)}
        result['buildings'][f.GetField('building_id')] = {
            'polygons': g.GetGeometryCount(),
            'min': [env[0], env[2], env[4]],
            'max': [env[1], env[3], env[5]],
            'volume': volume,
            'lonlat': [lon, lat],
            'attributes': attributes,
            'tags': {},
        }
    for s in ds.GetLayerByName('surfaces'):
        tags = result['buildings'][s.GetField('building_id')]['tags']
        tags[s.GetField('tag')] = tags.get(s.GetField('tag'), 0) + 1
    with open(out, 'w') as o:
        json.dump(result, o)


main()
