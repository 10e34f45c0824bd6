from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.atlas_out import AtlasOut
from ...models.atlas_request import AtlasRequest
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: AtlasRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/atlas",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> AtlasOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = AtlasOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[AtlasOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: AtlasRequest,
) -> Response[AtlasOut | ErrorOut]:
    """The stability atlas of the held tip over a small grid of deflections

     With the tip held at every target `(dx, dy)` of the grid, every equilibrium is found and counted
    (minima, saddles, maxima; the least-energy stable one and its sign string); then each grid edge is
    followed by continuation: where a stable branch loses stability on it (a fold: the arm snaps) is a
    `branch_end` crossing, where the least-energy branch changes a `switch` (the point of equal energy),
    each located on the edge (`tensegrity_opt.stability_atlas`). `curves` joins the crossings of one
    kind inside each grid cell into segments. `edges: false` gives the counts only. The counts are
    certified with `method: homotopy` (`certified`), measured with the search. The grid is `dx x dy`
    (each a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy.

    Args:
        body (AtlasRequest): The stability atlas of the held tip over the grid `dx x dy`
            (`tensegrity_opt.stability_atlas`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[AtlasOut | ErrorOut]
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
    body: AtlasRequest,
) -> AtlasOut | ErrorOut | None:
    """The stability atlas of the held tip over a small grid of deflections

     With the tip held at every target `(dx, dy)` of the grid, every equilibrium is found and counted
    (minima, saddles, maxima; the least-energy stable one and its sign string); then each grid edge is
    followed by continuation: where a stable branch loses stability on it (a fold: the arm snaps) is a
    `branch_end` crossing, where the least-energy branch changes a `switch` (the point of equal energy),
    each located on the edge (`tensegrity_opt.stability_atlas`). `curves` joins the crossings of one
    kind inside each grid cell into segments. `edges: false` gives the counts only. The counts are
    certified with `method: homotopy` (`certified`), measured with the search. The grid is `dx x dy`
    (each a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy.

    Args:
        body (AtlasRequest): The stability atlas of the held tip over the grid `dx x dy`
            (`tensegrity_opt.stability_atlas`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        AtlasOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: AtlasRequest,
) -> Response[AtlasOut | ErrorOut]:
    """The stability atlas of the held tip over a small grid of deflections

     With the tip held at every target `(dx, dy)` of the grid, every equilibrium is found and counted
    (minima, saddles, maxima; the least-energy stable one and its sign string); then each grid edge is
    followed by continuation: where a stable branch loses stability on it (a fold: the arm snaps) is a
    `branch_end` crossing, where the least-energy branch changes a `switch` (the point of equal energy),
    each located on the edge (`tensegrity_opt.stability_atlas`). `curves` joins the crossings of one
    kind inside each grid cell into segments. `edges: false` gives the counts only. The counts are
    certified with `method: homotopy` (`certified`), measured with the search. The grid is `dx x dy`
    (each a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy.

    Args:
        body (AtlasRequest): The stability atlas of the held tip over the grid `dx x dy`
            (`tensegrity_opt.stability_atlas`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[AtlasOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: AtlasRequest,
) -> AtlasOut | ErrorOut | None:
    """The stability atlas of the held tip over a small grid of deflections

     With the tip held at every target `(dx, dy)` of the grid, every equilibrium is found and counted
    (minima, saddles, maxima; the least-energy stable one and its sign string); then each grid edge is
    followed by continuation: where a stable branch loses stability on it (a fold: the arm snaps) is a
    `branch_end` crossing, where the least-energy branch changes a `switch` (the point of equal energy),
    each located on the edge (`tensegrity_opt.stability_atlas`). `curves` joins the crossings of one
    kind inside each grid cell into segments. `edges: false` gives the counts only. The counts are
    certified with `method: homotopy` (`certified`), measured with the search. The grid is `dx x dy`
    (each a list or `{start, stop, num}`, strictly increasing); at most the server's
    `TENSEGRITY_MAX_ATLAS_TARGETS` targets (default 400; above: 422 `atlas_too_large`: submit the grid
    as a job, `POST /v1/jobs` with `analysis: atlas`, then `GET /v1/jobs/{id}/atlas`). Chains of 2 to 64
    segments; `method: homotopy` up to the server's `homotopy_max_segments`. The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`; targets
    not computed carry `error: "time_limit: ..."`) instead of a 504. A target costs ~40-150 ms with the
    search, seconds with the homotopy.

    Args:
        body (AtlasRequest): The stability atlas of the held tip over the grid `dx x dy`
            (`tensegrity_opt.stability_atlas`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        AtlasOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
