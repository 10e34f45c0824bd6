from http import HTTPStatus
from io import BytesIO
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.plot_atlas_grid_request import PlotAtlasGridRequest
from ...models.plot_atlas_job_request import PlotAtlasJobRequest
from ...types import File, Response


def _get_kwargs(
    *,
    body: PlotAtlasGridRequest | PlotAtlasJobRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/plots/atlas",
    }

    if isinstance(body, PlotAtlasGridRequest):
        _kwargs["json"] = body.to_dict()
    else:
        _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | File | None:
    if response.status_code == 200:
        response_200 = File(payload=BytesIO(response.content))

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 404:
        response_404 = ErrorOut.from_dict(response.json())

        return response_404

    if response.status_code == 409:
        response_409 = ErrorOut.from_dict(response.json())

        return response_409

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | File]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotAtlasGridRequest | PlotAtlasJobRequest,
) -> Response[ErrorOut | File]:
    """Figure: the stability atlas, stable equilibria over (dx, dy) with the switch and branch-end curves

     The number of stable equilibria of the held tip as a map over the deflection (one cell per target,
    one colour per count, unreachable targets hatched light grey, failed ones dark), the curves where
    the least-energy branch switches (solid) and where stable branches end (dashed) with their crossings
    marked, the legend beside the axes. Body: that of `/v1/atlas` (the atlas computed for the figure),
    or `{"job": id}` for a finished atlas job (`GET /v1/jobs/{id}/atlas`: 404 for an unknown job, 409
    `job_not_done`, 422 `invalid_parameter` on `job` for another analysis). The grid is `dx x dy` (each
    a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy. Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotAtlasGridRequest | PlotAtlasJobRequest): the body of /v1/atlas (plus format,
            dpi), or {"job": id} for a finished atlas job

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: PlotAtlasGridRequest | PlotAtlasJobRequest,
) -> ErrorOut | File | None:
    """Figure: the stability atlas, stable equilibria over (dx, dy) with the switch and branch-end curves

     The number of stable equilibria of the held tip as a map over the deflection (one cell per target,
    one colour per count, unreachable targets hatched light grey, failed ones dark), the curves where
    the least-energy branch switches (solid) and where stable branches end (dashed) with their crossings
    marked, the legend beside the axes. Body: that of `/v1/atlas` (the atlas computed for the figure),
    or `{"job": id}` for a finished atlas job (`GET /v1/jobs/{id}/atlas`: 404 for an unknown job, 409
    `job_not_done`, 422 `invalid_parameter` on `job` for another analysis). The grid is `dx x dy` (each
    a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy. Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotAtlasGridRequest | PlotAtlasJobRequest): the body of /v1/atlas (plus format,
            dpi), or {"job": id} for a finished atlas job

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotAtlasGridRequest | PlotAtlasJobRequest,
) -> Response[ErrorOut | File]:
    """Figure: the stability atlas, stable equilibria over (dx, dy) with the switch and branch-end curves

     The number of stable equilibria of the held tip as a map over the deflection (one cell per target,
    one colour per count, unreachable targets hatched light grey, failed ones dark), the curves where
    the least-energy branch switches (solid) and where stable branches end (dashed) with their crossings
    marked, the legend beside the axes. Body: that of `/v1/atlas` (the atlas computed for the figure),
    or `{"job": id}` for a finished atlas job (`GET /v1/jobs/{id}/atlas`: 404 for an unknown job, 409
    `job_not_done`, 422 `invalid_parameter` on `job` for another analysis). The grid is `dx x dy` (each
    a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy. Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotAtlasGridRequest | PlotAtlasJobRequest): the body of /v1/atlas (plus format,
            dpi), or {"job": id} for a finished atlas job

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PlotAtlasGridRequest | PlotAtlasJobRequest,
) -> ErrorOut | File | None:
    """Figure: the stability atlas, stable equilibria over (dx, dy) with the switch and branch-end curves

     The number of stable equilibria of the held tip as a map over the deflection (one cell per target,
    one colour per count, unreachable targets hatched light grey, failed ones dark), the curves where
    the least-energy branch switches (solid) and where stable branches end (dashed) with their crossings
    marked, the legend beside the axes. Body: that of `/v1/atlas` (the atlas computed for the figure),
    or `{"job": id}` for a finished atlas job (`GET /v1/jobs/{id}/atlas`: 404 for an unknown job, 409
    `job_not_done`, 422 `invalid_parameter` on `job` for another analysis). The grid is `dx x dy` (each
    a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy. Answers `image/png`, or `image/svg+xml` with `"format": "svg"`
    (or, without `format`, an `Accept` header preferring `image/svg+xml`); `dpi` sets the PNG
    resolution.

    Args:
        body (PlotAtlasGridRequest | PlotAtlasJobRequest): the body of /v1/atlas (plus format,
            dpi), or {"job": id} for a finished atlas job

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
