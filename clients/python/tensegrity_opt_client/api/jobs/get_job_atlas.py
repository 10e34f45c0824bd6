from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.atlas_out import AtlasOut
from ...models.error_out import ErrorOut
from ...types import UNSET, Response, Unset


def _get_kwargs(
    job_id: str,
    *,
    edges: bool | Unset = True,
) -> dict[str, Any]:

    params: dict[str, Any] = {}

    params["edges"] = edges

    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs/{job_id}/atlas".format(
            job_id=quote(str(job_id), safe=""),
        ),
        "params": params,
    }

    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> AtlasOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = AtlasOut.from_dict(response.json())

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
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    edges: bool | Unset = True,
) -> Response[AtlasOut | ErrorOut]:
    """The stability atlas of a finished atlas job

     For a job with `analysis: atlas` over a grid in `dx` and `dy` that is `done`: the atlas
    (`tensegrity_opt.applications.sweeps.atlas_from_rows`: each stored stable equilibrium re-solved,
    then the grid edges analysed for the least-energy switches and the branch ends), the body of `POST
    /v1/atlas` for the same grid. Targets whose point failed are in it with their `error` (`status:
    partial`). `edges=false`: the counts only. The edge analysis stops shortly before the server's time
    limit and answers what it has (`status: "time_limit"`) instead of a 504. A job not done yet: 409
    `job_not_done`; another analysis, or an atlas not over dx x dy: 422 `invalid_parameter` on
    `spec.analysis` / `spec.grid`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):
        edges (bool | Unset): locate the switches and branch ends on the grid edges Default: True.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[AtlasOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
        edges=edges,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    edges: bool | Unset = True,
) -> AtlasOut | ErrorOut | None:
    """The stability atlas of a finished atlas job

     For a job with `analysis: atlas` over a grid in `dx` and `dy` that is `done`: the atlas
    (`tensegrity_opt.applications.sweeps.atlas_from_rows`: each stored stable equilibrium re-solved,
    then the grid edges analysed for the least-energy switches and the branch ends), the body of `POST
    /v1/atlas` for the same grid. Targets whose point failed are in it with their `error` (`status:
    partial`). `edges=false`: the counts only. The edge analysis stops shortly before the server's time
    limit and answers what it has (`status: "time_limit"`) instead of a 504. A job not done yet: 409
    `job_not_done`; another analysis, or an atlas not over dx x dy: 422 `invalid_parameter` on
    `spec.analysis` / `spec.grid`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):
        edges (bool | Unset): locate the switches and branch ends on the grid edges Default: True.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        AtlasOut | ErrorOut
    """

    return sync_detailed(
        job_id=job_id,
        client=client,
        edges=edges,
    ).parsed


async def asyncio_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    edges: bool | Unset = True,
) -> Response[AtlasOut | ErrorOut]:
    """The stability atlas of a finished atlas job

     For a job with `analysis: atlas` over a grid in `dx` and `dy` that is `done`: the atlas
    (`tensegrity_opt.applications.sweeps.atlas_from_rows`: each stored stable equilibrium re-solved,
    then the grid edges analysed for the least-energy switches and the branch ends), the body of `POST
    /v1/atlas` for the same grid. Targets whose point failed are in it with their `error` (`status:
    partial`). `edges=false`: the counts only. The edge analysis stops shortly before the server's time
    limit and answers what it has (`status: "time_limit"`) instead of a 504. A job not done yet: 409
    `job_not_done`; another analysis, or an atlas not over dx x dy: 422 `invalid_parameter` on
    `spec.analysis` / `spec.grid`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):
        edges (bool | Unset): locate the switches and branch ends on the grid edges Default: True.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[AtlasOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
        edges=edges,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    edges: bool | Unset = True,
) -> AtlasOut | ErrorOut | None:
    """The stability atlas of a finished atlas job

     For a job with `analysis: atlas` over a grid in `dx` and `dy` that is `done`: the atlas
    (`tensegrity_opt.applications.sweeps.atlas_from_rows`: each stored stable equilibrium re-solved,
    then the grid edges analysed for the least-energy switches and the branch ends), the body of `POST
    /v1/atlas` for the same grid. Targets whose point failed are in it with their `error` (`status:
    partial`). `edges=false`: the counts only. The edge analysis stops shortly before the server's time
    limit and answers what it has (`status: "time_limit"`) instead of a 504. A job not done yet: 409
    `job_not_done`; another analysis, or an atlas not over dx x dy: 422 `invalid_parameter` on
    `spec.analysis` / `spec.grid`. Someone else's job (API keys configured) is 404.

    Args:
        job_id (str):
        edges (bool | Unset): locate the switches and branch ends on the grid edges Default: True.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        AtlasOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            job_id=job_id,
            client=client,
            edges=edges,
        )
    ).parsed
