//! Statismo HDF5 model files, natively, through the HDF5 C library (crate `hdf5-metno`, Debian's
//! `libhdf5-dev`): [`write_statismo_h5`] writes a [`StatismoModel`] in statismo 0.9's layout,
//! [`read_statismo_h5`] reads one back. This module only moves datasets; the layout's meaning
//! and every check live in `crate::model_file::statismo`. Native only: the browser uses h5wasm.
//!
//! ```text
//! /version/majorVersion, /version/minorVersion     int32 scalars (0, 9)
//! /representer            attributes name, version, datasetType (strings)
//!   points  float32 3 × n     cells  uint32 3 × m     pointData/, cellData/ (empty groups)
//! /model/mean             float32 3n
//! /model/pcaBasis         float32 3n × k (orthonormal columns)
//! /model/pcaVariance      float32 k
//! /model/noiseVariance    float32 scalar
//! /modelinfo/build-time   string;  /modelinfo/scores float32 k × N (1 × 1 zero: none)
//! /modelinfo/modelBuilder-0/{builderName, buildTime}  strings
//! /modelinfo/modelBuilder-0/{dataInfo, parameters}/*  strings
//! ```

use std::path::Path;
use std::str::FromStr;

use hdf5::types::VarLenUnicode;
use hdf5::{Group, H5Type};

use crate::model_file::file::MAX_MODEL_BYTES;
use crate::model_file::statismo::{
    RowMajor, StatismoModel, BUILDER_NAME, DATASET_TYPE, REPRESENTER_NAME, REPRESENTER_VERSION,
};
use crate::pca::PcaError;

fn h5(path: &Path) -> impl Fn(hdf5::Error) -> PcaError + '_ {
    move |e| PcaError::Statismo(format!("{}: {e}", path.display()))
}

fn text(s: &str) -> VarLenUnicode {
    // Text with a NUL cannot be an HDF5 string; such a subject name loses the rest.
    VarLenUnicode::from_str(s.split('\0').next().unwrap_or_default()).unwrap_or_default()
}

fn write_string(group: &Group, name: &str, value: &str) -> hdf5::Result<()> {
    group
        .new_dataset::<VarLenUnicode>()
        .create(name)?
        .write_scalar(&text(value))
}

fn write_matrix<T: H5Type>(group: &Group, name: &str, m: &RowMajor<T>) -> hdf5::Result<()> {
    group
        .new_dataset::<T>()
        .shape([m.rows, m.cols])
        .create(name)?
        .write_raw(m.data.as_slice())
}

/// Writes `model` to `path` (replacing it) in statismo 0.9's layout; `build_time` is the text
/// of `/modelinfo/build-time`.
pub fn write_statismo_h5(
    path: &Path,
    model: &StatismoModel,
    build_time: &str,
) -> Result<(), PcaError> {
    write(path, model, build_time).map_err(h5(path))
}

fn write(path: &Path, model: &StatismoModel, build_time: &str) -> hdf5::Result<()> {
    let file = hdf5::File::create(path)?;
    let version = file.create_group("version")?;
    let (major, minor) = model
        .version
        .unwrap_or(crate::model_file::statismo::VERSION);
    version
        .new_dataset::<i32>()
        .create("majorVersion")?
        .write_scalar(&major)?;
    version
        .new_dataset::<i32>()
        .create("minorVersion")?
        .write_scalar(&minor)?;

    let representer = file.create_group("representer")?;
    for (name, value) in [
        ("name", REPRESENTER_NAME),
        ("version", REPRESENTER_VERSION),
        ("datasetType", DATASET_TYPE),
    ] {
        representer
            .new_attr::<VarLenUnicode>()
            .create(name)?
            .write_scalar(&text(value))?;
    }
    write_matrix(&representer, "points", &model.points)?;
    write_matrix(&representer, "cells", &model.cells)?;
    representer.create_group("pointData")?;
    representer.create_group("cellData")?;

    let m = file.create_group("model")?;
    m.new_dataset::<f32>()
        .shape([model.mean.len()])
        .create("mean")?
        .write_raw(model.mean.as_slice())?;
    write_matrix(&m, "pcaBasis", &model.pca_basis)?;
    m.new_dataset::<f32>()
        .shape([model.pca_variance.len()])
        .create("pcaVariance")?
        .write_raw(model.pca_variance.as_slice())?;
    m.new_dataset::<f32>()
        .create("noiseVariance")?
        .write_scalar(&model.noise_variance)?;

    let info = file.create_group("modelinfo")?;
    write_string(&info, "build-time", build_time)?;
    if model.scores.data.is_empty() {
        // statismo's "no scores": HDF5 has no empty matrix.
        write_matrix(
            &info,
            "scores",
            &RowMajor {
                rows: 1,
                cols: 1,
                data: vec![0.0f32],
            },
        )?;
    } else {
        write_matrix(&info, "scores", &model.scores)?;
    }
    let builder = info.create_group("modelBuilder-0")?;
    write_string(&builder, "builderName", BUILDER_NAME)?;
    write_string(&builder, "buildTime", build_time)?;
    for (group, entries) in [
        ("dataInfo", &model.data_info),
        ("parameters", &model.parameters),
    ] {
        let g = builder.create_group(group)?;
        for (key, value) in entries {
            write_string(&g, key, value)?;
        }
    }
    file.close()
}

/// Reads the datasets of a statismo model from `path` (float or double, any integer type for
/// the cells), without judging them: `model_file::statismo::check_statismo` does. A file larger than
/// `model_file::file::MAX_MODEL_BYTES`, or a dataset that would take more, is refused before reading.
pub fn read_statismo_h5(path: &Path) -> Result<StatismoModel, PcaError> {
    let bytes = std::fs::metadata(path)
        .map_err(|e| PcaError::Statismo(format!("{}: {e}", path.display())))?
        .len();
    if bytes > MAX_MODEL_BYTES {
        return Err(PcaError::TooLarge {
            bytes,
            limit: MAX_MODEL_BYTES,
        });
    }
    hdf5::silence_errors(true);
    read(path).map_err(h5(path))
}

fn matrix<T: H5Type>(file: &hdf5::File, name: &str) -> hdf5::Result<RowMajor<T>> {
    let ds = file.dataset(name)?;
    let shape = ds.shape();
    let count: usize = shape.iter().product();
    if count.saturating_mul(std::mem::size_of::<T>()) as u64 > MAX_MODEL_BYTES {
        return Err(format!("{name} holds {count} values, more than a model may").into());
    }
    let (rows, cols) = match shape.as_slice() {
        [] => (1, 1),
        [n] => (*n, 1),
        [r, c] => (*r, *c),
        _ => return Err(format!("{name} has {} dimensions, not 1 or 2", shape.len()).into()),
    };
    Ok(RowMajor {
        rows,
        cols,
        data: ds.read_raw::<T>()?,
    })
}

fn read(path: &Path) -> hdf5::Result<StatismoModel> {
    let file = hdf5::File::open(path)?;
    let version = if file.link_exists("version") {
        let v = |name: &str| -> hdf5::Result<i32> { file.dataset(name)?.read_scalar::<i32>() };
        Some((v("version/majorVersion")?, v("version/minorVersion")?))
    } else {
        None
    };
    let noise = matrix::<f32>(&file, "model/noiseVariance")?;
    let scores = if file.link_exists("modelinfo") && file.group("modelinfo")?.link_exists("scores")
    {
        let s = matrix::<f32>(&file, "modelinfo/scores")?;
        // statismo's "no scores" is a 1 × 1 zero.
        if s.rows * s.cols == 1 && s.data[0] == 0.0 {
            RowMajor::default()
        } else {
            s
        }
    } else {
        RowMajor::default()
    };
    Ok(StatismoModel {
        version,
        points: matrix(&file, "representer/points")?,
        cells: matrix(&file, "representer/cells")?,
        mean: matrix(&file, "model/mean")?.data,
        pca_basis: matrix(&file, "model/pcaBasis")?,
        pca_variance: matrix(&file, "model/pcaVariance")?.data,
        noise_variance: noise.data.first().copied().unwrap_or(0.0),
        scores,
        data_info: Vec::new(),
        parameters: Vec::new(),
    })
}
